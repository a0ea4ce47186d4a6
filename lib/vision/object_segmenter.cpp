#include "opf/vision/object_segmenter.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace opf::vision {

namespace {

void check(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("segmenter: " + message);
}

void check_hsv(const std::array<int, 3>& hsv, const char* which) {
  check(hsv[0] >= 0 && hsv[0] <= 179, std::string("hsv ") + which + " hue must be in 0..179");
  check(hsv[1] >= 0 && hsv[1] <= 255 && hsv[2] >= 0 && hsv[2] <= 255,
        std::string("hsv ") + which + " saturation and value must be in 0..255");
}

cv::Mat ellipse_kernel(int size) {
  return size > 1 ? cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size)) : cv::Mat();
}

/// The gap between two rectangles: 0 when they touch or overlap.
double gap(const cv::Rect& a, const cv::Rect& b) {
  const int dx = std::max({0, a.x - (b.x + b.width), b.x - (a.x + a.width)});
  const int dy = std::max({0, a.y - (b.y + b.height), b.y - (a.y + a.height)});
  return std::hypot(static_cast<double>(dx), static_cast<double>(dy));
}

}  // namespace

ObjectSegmenter::ObjectSegmenter(const SegmenterOptions& options) : options_(options) {
  check_hsv(options.hsv.low, "low");
  check_hsv(options.hsv.high, "high");
  check(options.hsv.low[1] <= options.hsv.high[1] && options.hsv.low[2] <= options.hsv.high[2],
        "hsv low saturation and value must not exceed the high ones");
  check(options.grey_threshold >= 0 && options.grey_threshold <= 255,
        "grey threshold must be in 0..255");
  check(options.open_px >= 0 && options.close_px >= 0, "kernel sizes must be >= 0");
  check(options.fragment_fraction >= 0.0 && options.fragment_fraction <= 1.0,
        "fragment fraction must be in [0, 1]");
  check(options.fragment_distance_px >= 0.0, "fragment distance must be >= 0");
  check(options.min_area_px >= 0.0, "minimum area must be >= 0");
  check(
      options.roi.x >= 0 && options.roi.y >= 0 && options.roi.width >= 0 && options.roi.height >= 0,
      "region of interest must have non-negative origin and size");
  const BackgroundOptions& b = options.background;
  check(b.history >= 1, "background history must be >= 1 frame");
  check(b.var_threshold > 0.0, "background variance threshold must be > 0");
  check(b.learning_rate == -1.0 || (b.learning_rate >= 0.0 && b.learning_rate <= 1.0),
        "background learning rate must be in [0, 1] or -1");
  check(b.gate_px > 0.0, "association gate must be > 0");
  if (options.method == SegmentationMethod::kBackground)
    background_ = cv::createBackgroundSubtractorMOG2(b.history, b.var_threshold, b.shadows);
  open_kernel_ = ellipse_kernel(options.open_px);
  close_kernel_ = ellipse_kernel(options.close_px);
}

void ObjectSegmenter::make_candidates(const cv::Mat& bgr) {
  const HsvRange& hsv = options_.hsv;
  switch (options_.method) {
    case SegmentationMethod::kHsv: {
      cv::cvtColor(bgr, scratch_, cv::COLOR_BGR2HSV);
      const auto bound = [](int h, const std::array<int, 3>& sv) {
        return cv::Scalar(h, sv[1], sv[2]);
      };
      if (hsv.low[0] <= hsv.high[0]) {
        cv::inRange(scratch_, bound(hsv.low[0], hsv.low), bound(hsv.high[0], hsv.high),
                    candidates_);
      } else {  // wraps around red: low..179 and 0..high
        cv::Mat upper;
        cv::inRange(scratch_, bound(hsv.low[0], hsv.low), bound(179, hsv.high), candidates_);
        cv::inRange(scratch_, bound(0, hsv.low), bound(hsv.high[0], hsv.high), upper);
        candidates_ |= upper;
      }
      break;
    }
    case SegmentationMethod::kDark:
      cv::cvtColor(bgr, scratch_, cv::COLOR_BGR2GRAY);
      // THRESH_BINARY_INV keeps grey <= threshold.
      cv::threshold(scratch_, candidates_, options_.grey_threshold, 255, cv::THRESH_BINARY_INV);
      break;
    case SegmentationMethod::kLight:
      cv::cvtColor(bgr, scratch_, cv::COLOR_BGR2GRAY);
      // THRESH_BINARY keeps grey > threshold - 1, i.e. grey >= threshold.
      cv::threshold(scratch_, candidates_, options_.grey_threshold - 1, 255, cv::THRESH_BINARY);
      break;
    case SegmentationMethod::kBackground:
      background_->apply(bgr, scratch_, options_.background.learning_rate);
      // MOG2 marks foreground 255 and shadows 127: shadows are never the object.
      cv::threshold(scratch_, candidates_, 200, 255, cv::THRESH_BINARY);
      break;
  }
  if (!options_.roi.empty()) {
    const cv::Rect roi = options_.roi & cv::Rect(0, 0, bgr.cols, bgr.rows);
    if (roi.empty())
      throw std::invalid_argument("segmenter: the region of interest lies outside the " +
                                  std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows) +
                                  " frame");
    cv::Mat inside = cv::Mat::zeros(candidates_.size(), CV_8UC1);
    candidates_(roi).copyTo(inside(roi));
    candidates_ = inside;
  }
  if (!open_kernel_.empty())
    cv::morphologyEx(candidates_, candidates_, cv::MORPH_OPEN, open_kernel_);
  if (!close_kernel_.empty())
    cv::morphologyEx(candidates_, candidates_, cv::MORPH_CLOSE, close_kernel_);
}

int ObjectSegmenter::component_area(int label) const {
  return stats_.at<int>(label, cv::CC_STAT_AREA);
}

cv::Rect ObjectSegmenter::component_box(int label) const {
  return {stats_.at<int>(label, cv::CC_STAT_LEFT), stats_.at<int>(label, cv::CC_STAT_TOP),
          stats_.at<int>(label, cv::CC_STAT_WIDTH), stats_.at<int>(label, cv::CC_STAT_HEIGHT)};
}

int ObjectSegmenter::choose_component(int count, bool tracking) const {
  int anchor = 0;
  if (!tracking) {
    for (int label = 1; label < count; ++label)
      if (anchor == 0 || component_area(label) > component_area(anchor)) anchor = label;
    return anchor;
  }
  // Specks below the fragment share of the minimum area are never taken for the object.
  const cv::Point2d reference = last_centroid_.value_or(options_.background.start);
  double nearest = options_.background.gate_px;
  for (int label = 1; label < count; ++label) {
    if (component_area(label) < options_.fragment_fraction * options_.min_area_px) continue;
    const cv::Point2d centroid(centroids_.at<double>(label, 0), centroids_.at<double>(label, 1));
    const double distance = cv::norm(centroid - reference);
    if (distance <= nearest) {
      nearest = distance;
      anchor = label;
    }
  }
  return anchor;
}

Blob ObjectSegmenter::merge_fragments(int count, int anchor) {
  std::vector<unsigned char> keep(static_cast<std::size_t>(count), 0);
  keep[static_cast<std::size_t>(anchor)] = 1;
  Blob blob;
  blob.bounds = component_box(anchor);
  blob.components = 1;
  for (int label = 1; label < count; ++label) {
    if (label == anchor) continue;
    if (component_area(label) >= options_.fragment_fraction * component_area(anchor) &&
        gap(component_box(label), component_box(anchor)) <= options_.fragment_distance_px) {
      keep[static_cast<std::size_t>(label)] = 1;
      blob.bounds |= component_box(label);
      ++blob.components;
    }
  }
  for (int row = 0; row < labels_.rows; ++row) {
    const int* label = labels_.ptr<int>(row);
    unsigned char* out = object_.ptr<unsigned char>(row);
    for (int col = 0; col < labels_.cols; ++col)
      if (keep[static_cast<std::size_t>(label[col])]) out[col] = 255;
  }
  return blob;
}

std::optional<Blob> ObjectSegmenter::segment(const cv::Mat& bgr, std::size_t frame_index) {
  if (bgr.type() != CV_8UC3 || bgr.empty())
    throw std::invalid_argument("segmenter: expected a non-empty 8-bit BGR image");
  if (frame_size_.empty()) frame_size_ = bgr.size();
  if (bgr.size() != frame_size_)
    throw std::invalid_argument("segmenter: the frame size changed from " +
                                std::to_string(frame_size_.width) + "x" +
                                std::to_string(frame_size_.height) + " to " +
                                std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows));
  make_candidates(bgr);
  object_ = cv::Mat::zeros(bgr.size(), CV_8UC1);
  const bool tracking = options_.method == SegmentationMethod::kBackground;
  if (tracking && frame_index < options_.background.start_frame) return std::nullopt;

  const int count =
      cv::connectedComponentsWithStats(candidates_, labels_, stats_, centroids_, 8, CV_32S);
  const int anchor = choose_component(count, tracking);
  if (anchor == 0) return std::nullopt;
  Blob blob = merge_fragments(count, anchor);
  blob.moments = cv::moments(object_, true);
  blob.area_px = blob.moments.m00;
  if (blob.area_px <= 0.0 || blob.area_px < options_.min_area_px) {
    object_.setTo(0);
    return std::nullopt;
  }
  blob.centroid_px =
      cv::Point2d(blob.moments.m10 / blob.moments.m00, blob.moments.m01 / blob.moments.m00);
  if (tracking) last_centroid_ = blob.centroid_px;
  return blob;
}

}  // namespace opf::vision
