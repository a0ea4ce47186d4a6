#include "opf/vision/detection_overlay.h"

#include <opencv2/imgproc.hpp>

#include <array>
#include <cmath>

namespace opf::vision {

cv::Mat draw_detection_overlay(const FrameResult& result, const std::vector<std::string>& names) {
  static const std::array<cv::Scalar, 4> kColours = {cv::Scalar(255, 0, 255),
                                                     cv::Scalar(255, 255, 0), cv::Scalar(0, 0, 255),
                                                     cv::Scalar(0, 255, 0)};
  cv::Mat overlay = result.bgr.clone();
  // Candidate pixels that were not taken for the object: greyed out.
  for (std::size_t i = 0; i < result.segmenters.size(); ++i) {
    const cv::Mat& candidates = result.segmenters[i].candidate_mask();
    if (candidates.size() != overlay.size()) continue;
    cv::Mat rejected = candidates & ~result.segmenters[i].object_mask();
    cv::Mat grey;
    cv::addWeighted(overlay, 0.4,
                    cv::Mat(overlay.size(), overlay.type(), cv::Scalar(255, 255, 255)), 0.6, 0.0,
                    grey);
    grey.copyTo(overlay, rejected);
  }
  int missing_line = 0;
  for (std::size_t i = 0; i < result.blobs.size(); ++i) {
    const cv::Scalar colour = kColours[i % kColours.size()];
    const std::string& name = i < names.size() ? names[i] : std::string("object");
    if (!result.blobs[i]) {
      cv::putText(overlay, name + ": not found", cv::Point(8, 20 + 20 * missing_line++),
                  cv::FONT_HERSHEY_SIMPLEX, 0.6, colour, 2);
      continue;
    }
    const Blob& blob = *result.blobs[i];
    cv::Mat tint(overlay.size(), overlay.type(), colour);
    cv::Mat blended;
    cv::addWeighted(overlay, 0.5, tint, 0.5, 0.0, blended);
    blended.copyTo(overlay, result.segmenters[i].object_mask());
    const cv::Point centre(static_cast<int>(std::lround(blob.centroid_px.x)),
                           static_cast<int>(std::lround(blob.centroid_px.y)));
    cv::drawMarker(overlay, centre, cv::Scalar(0, 0, 0), cv::MARKER_CROSS, 21, 4);
    cv::drawMarker(overlay, centre, colour, cv::MARKER_CROSS, 21, 2);
    const double angle = principal_axis_angle(blob.moments);
    const double half = 0.5 * std::max(blob.bounds.width, blob.bounds.height);
    const cv::Point2d axis(half * std::cos(angle), half * std::sin(angle));
    cv::line(overlay, blob.centroid_px - axis, blob.centroid_px + axis, colour, 2);
    cv::rectangle(overlay, blob.bounds, colour, 1);
    cv::putText(overlay, name, blob.bounds.tl() + cv::Point(0, -4), cv::FONT_HERSHEY_SIMPLEX, 0.6,
                colour, 2);
  }
  cv::putText(overlay, "frame " + std::to_string(result.frame), cv::Point(8, overlay.rows - 10),
              cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(0, 0, 255), 2);
  return overlay;
}

}  // namespace opf::vision
