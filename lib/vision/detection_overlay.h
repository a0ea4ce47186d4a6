#pragma once
// A picture of what `opf detect` found in a frame, to check a segmentation by eye: each object's
// pixels tinted, its centroid marked, its principal axis drawn and its name written beside it; the
// candidate pixels that were not taken for the object whitened.

#include "opf/vision/video_detection.h"

#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

namespace opf::vision {

/// `result.bgr` with the objects drawn over it; `names` in the order of result.blobs. Objects not
/// found in the frame are listed as such in the top-left corner.
cv::Mat draw_detection_overlay(const FrameResult& result, const std::vector<std::string>& names);

}  // namespace opf::vision
