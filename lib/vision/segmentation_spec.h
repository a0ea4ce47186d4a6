#pragma once
// The YAML file that tells `opf detect` which objects to find in a video and how: per named object
// one segmentation (an HSV range, a dark or light grey-level threshold, or background subtraction
// with nearest-neighbour association), its clean-up, and how its blob becomes a pose.
//
//   objects:
//     box:                                   # the object's name in the measurement log
//       hsv: {low: [15, 100, 80], high: [35, 255, 255]}  # OpenCV HSV: h 0-179, s and v 0-255
//       # or  dark: 60          (grey level <= 60)
//       # or  light: 200        (grey level >= 200)
//       # or  background: {start: [250, 490], start_frame: 585, gate: 40,
//       #                  history: 200, var_threshold: 16, shadows: true, learning_rate: -1}
//       morphology: {open: 3, close: 3}      # elliptic kernel sizes in px (0 or 1: none)
//       fragments: {fraction: 0.25, distance: 30}  # merge components >= fraction of the chosen
//                                                  # one's area within distance px of it
//       roi: [x, y, width, height]           # optional, px
//       min_area: 50                         # px; a smaller blob is no detection
//       pose: {metres_per_pixel: 0.001, reference_depth: 1.0, reference_area: 30000,
//              reference_frames: 5}          # see blob_pose.h; reference_area optional
//
// Unknown keys are errors (with a suggestion for near misses), as are values out of range; every
// error is an InputError naming the file, the line, the key path and what was expected.

#include "opf/vision/blob_pose.h"
#include "opf/vision/object_segmenter.h"

#include <filesystem>
#include <string>
#include <vector>

namespace opf::vision {

struct ObjectSpec {
  std::string name;
  SegmenterOptions segmentation;
  BlobPoseOptions pose;
};

struct SegmentationSpec {
  std::vector<ObjectSpec> objects;  ///< in file order, at least one
};

/// Parses the YAML `text`; `source_name` is the file name errors give.
SegmentationSpec parse_segmentation_spec(const std::string& text, const std::string& source_name);

/// Reads the file at `path`; InputError also when it cannot be opened.
SegmentationSpec load_segmentation_spec(const std::filesystem::path& path);

}  // namespace opf::vision
