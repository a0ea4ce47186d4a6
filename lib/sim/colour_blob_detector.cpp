#include "opf/sim/colour_blob_detector.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace opf::sim {
namespace {

// OpenCV's 8-bit HSV of one colour: hue 0-179 (degrees / 2), saturation and value 0-255.
cv::Vec3b hsv_of(const Colour& colour) {
  cv::Mat bgr(1, 1, CV_8UC3, cv::Scalar(colour.b, colour.g, colour.r));
  cv::Mat hsv;
  cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
  return hsv.at<cv::Vec3b>(0, 0);
}

}  // namespace

bool segmentable(const Colour& colour, const ColourBlobDetectorOptions& options) {
  const cv::Vec3b hsv = hsv_of(colour);
  return hsv[1] >= options.min_saturation && hsv[2] >= options.min_value;
}

bool confusable(const Colour& tracked, const Colour& other,
                const ColourBlobDetectorOptions& options) {
  if (!segmentable(other, options)) return false;
  // OpenCV's 8-bit hue is in 2-degree units, 0 to 179, circular.
  const int apart = std::abs(int{hsv_of(tracked)[0]} - int{hsv_of(other)[0]});
  const int tolerance = static_cast<int>(std::lround(0.5 * options.hue_tolerance_deg));
  return std::min(apart, 180 - apart) <= 2 * tolerance;
}

ColourBlobDetector::ColourBlobDetector(const ColourBlobDetectorOptions& options)
    : options_(options) {
  if (!(options_.hue_tolerance_deg >= 0.0 && options_.hue_tolerance_deg < 90.0)) {
    throw std::invalid_argument("ColourBlobDetectorOptions: hue_tolerance_deg must be in [0, 90)");
  }
  if (options_.min_saturation < 0 || options_.min_value < 0 || options_.min_area_pixels < 0) {
    throw std::invalid_argument("ColourBlobDetectorOptions: minimums must be >= 0");
  }
}

void ColourBlobDetector::convert(const cv::Mat& bgr, const cv::Mat& depth) {
  if (bgr.type() != CV_8UC3 || depth.type() != CV_32FC1 || bgr.size() != depth.size()) {
    throw std::invalid_argument(
        "ColourBlobDetector: need a CV_8UC3 BGR image and a CV_32FC1 depth image of one size");
  }
  cv::cvtColor(bgr, hsv_, cv::COLOR_BGR2HSV);
}

std::optional<BlobMeasurement> ColourBlobDetector::detect(const cv::Mat& bgr, const cv::Mat& depth,
                                                          const Colour& colour,
                                                          const CameraModel& camera) {
  convert(bgr, depth);
  return detect_in_hsv(depth, colour, camera);
}

std::vector<std::optional<BlobMeasurement>> ColourBlobDetector::detect_tracked(
    const cv::Mat& bgr, const cv::Mat& depth, const std::vector<Body>& bodies,
    const CameraModel& camera) {
  convert(bgr, depth);
  std::vector<std::optional<BlobMeasurement>> result(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].tracked) result[i] = detect_in_hsv(depth, bodies[i].colour, camera);
  }
  return result;
}

std::optional<BlobMeasurement> ColourBlobDetector::detect_in_hsv(const cv::Mat& depth,
                                                                 const Colour& colour,
                                                                 const CameraModel& camera) {
  if (!segmentable(colour, options_)) {
    throw std::invalid_argument(
        "ColourBlobDetector: a tracked body's colour is below min_saturation or min_value; "
        "pick a saturated colour (see opf::sim::palette)");
  }
  const cv::Vec3b target = hsv_of(colour);
  // Hue is circular (0 and 179 are neighbours): a band crossing either end is split in two.
  const int hue = target[0];
  const int tolerance = static_cast<int>(std::lround(0.5 * options_.hue_tolerance_deg));
  const int low = hue - tolerance;
  const int high = hue + tolerance;
  const cv::Scalar sv_low(0, options_.min_saturation, options_.min_value);
  const auto in_band = [&](int h0, int h1, cv::Mat& out) {
    cv::inRange(hsv_, cv::Scalar(h0, sv_low[1], sv_low[2]), cv::Scalar(h1, 255, 255), out);
  };
  in_band(std::max(low, 0), std::min(high, 179), mask_);
  if (low < 0 || high > 179) {
    if (low < 0) {
      in_band(180 + low, 179, wrap_mask_);
    } else {
      in_band(0, high - 180, wrap_mask_);
    }
    cv::bitwise_or(mask_, wrap_mask_, mask_);
  }

  // Label only the mask's bounding box: a body covers a small part of the frame, and labelling
  // the whole frame would cost ~0.8 ms per colour.
  const cv::Rect roi = cv::boundingRect(mask_);
  if (roi.area() == 0) return std::nullopt;
  const int count =
      cv::connectedComponentsWithStats(mask_(roi), labels_, stats_, centroids_, 8, CV_32S);
  int best = 0;
  int best_area = 0;
  for (int label = 1; label < count; ++label) {
    const int area = stats_.at<int>(label, cv::CC_STAT_AREA);
    if (area > best_area) {
      best_area = area;
      best = label;
    }
  }
  if (best == 0 || best_area < options_.min_area_pixels) return std::nullopt;

  // One robust depth for a blob that spans a range of depths (a sphere's disc, a mug's rim and
  // side).
  const int left = stats_.at<int>(best, cv::CC_STAT_LEFT);
  const int top = stats_.at<int>(best, cv::CC_STAT_TOP);
  const int w = stats_.at<int>(best, cv::CC_STAT_WIDTH);
  const int h = stats_.at<int>(best, cv::CC_STAT_HEIGHT);
  depths_.clear();
  for (int r = top; r < top + h; ++r) {
    const int* label_row = labels_.ptr<int>(r);
    const float* depth_row = depth.ptr<float>(r + roi.y) + roi.x;
    for (int c = left; c < left + w; ++c) {
      if (label_row[c] == best && depth_row[c] > 0.0f && std::isfinite(depth_row[c])) {
        depths_.push_back(depth_row[c]);
      }
    }
  }
  if (depths_.empty()) return std::nullopt;
  const auto middle = depths_.begin() + static_cast<std::ptrdiff_t>(depths_.size() / 2);
  std::nth_element(depths_.begin(), middle, depths_.end());

  BlobMeasurement blob;
  blob.centroid_px = Eigen::Vector2d(centroids_.at<double>(best, 0) + roi.x,
                                     centroids_.at<double>(best, 1) + roi.y);
  blob.area_px = static_cast<double>(best_area);
  blob.depth_m = static_cast<double>(*middle);
  blob.surface_point_world = camera.back_project(blob.centroid_px, blob.depth_m);
  return blob;
}

}  // namespace opf::sim
