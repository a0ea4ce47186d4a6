#pragma once
// Finds one object in the frames of a real video: a mask of candidate pixels (an HSV colour range,
// a dark or light grey-level threshold, or background subtraction), cleaned by morphological
// opening and closing, then one connected component (the largest, or for background subtraction
// the one nearest the object's previous position) with the further large fragments near it merged
// in, since a hand or a post in front of the object can cut it in two.

#include "opf/core/enum_names.h"

#include <opencv2/core.hpp>
#include <opencv2/video/background_segm.hpp>

#include <array>
#include <cstddef>
#include <optional>

namespace opf::vision {

enum class SegmentationMethod {
  kHsv,         ///< pixels inside an HSV range
  kDark,        ///< grey level <= threshold
  kLight,       ///< grey level >= threshold
  kBackground,  ///< foreground of cv::BackgroundSubtractorMOG2, nearest-neighbour association
};
/// The keys a segmentation spec names its method with.
inline constexpr EnumNames<SegmentationMethod, 4> kSegmentationMethodNames = {
    {{SegmentationMethod::kHsv, "hsv"},
     {SegmentationMethod::kDark, "dark"},
     {SegmentationMethod::kLight, "light"},
     {SegmentationMethod::kBackground, "background"}}};

/// OpenCV's 8-bit HSV: hue 0-179 (degrees / 2), saturation and value 0-255, bounds inclusive. A
/// range whose low hue is above its high hue wraps around red (e.g. 170..10).
struct HsvRange {
  std::array<int, 3> low{0, 0, 0};
  std::array<int, 3> high{179, 255, 255};
};

/// Background subtraction for one isolated mover.
struct BackgroundOptions {
  int history = 200;            ///< frames the MOG2 model remembers
  double var_threshold = 16.0;  ///< MOG2's squared Mahalanobis distance threshold
  bool shadows = true;          ///< detect shadows (then never taken as the object)
  double learning_rate = -1.0;  ///< in [0, 1], or -1 for MOG2's automatic rate
  /// The video frame at which the object is at `start`. Earlier frames only train the model.
  std::size_t start_frame = 0;
  cv::Point2d start{0.0, 0.0};  ///< pixel position of the object at start_frame
  /// A component is the object when its centroid is within this many pixels of the object's last
  /// centroid (of `start` until the first detection); the nearest such component is taken.
  double gate_px = 50.0;
};

struct SegmenterOptions {
  SegmentationMethod method = SegmentationMethod::kHsv;
  HsvRange hsv;
  int grey_threshold = 128;  ///< for kDark and kLight, 0-255
  BackgroundOptions background;
  int open_px = 3;   ///< elliptic kernel size of the opening (removes specks); <= 1: none
  int close_px = 3;  ///< elliptic kernel size of the closing (fills holes); <= 1: none
  /// Further components are merged into the chosen one when their area is at least this fraction
  /// of its area and the gap between their bounding boxes is at most fragment_distance_px.
  double fragment_fraction = 0.25;
  double fragment_distance_px = 30.0;
  /// Pixels outside this rectangle are never the object; empty (the default) means the whole frame.
  cv::Rect roi;
  /// A blob (all merged components) smaller than this many pixels counts as no detection.
  double min_area_px = 50.0;
};

/// The object's pixels in one frame.
struct Blob {
  double area_px = 0.0;
  cv::Point2d centroid_px;  ///< mean pixel position (pixel centres at integer coordinates)
  cv::Moments moments;      ///< of the binary mask of the merged components
  cv::Rect bounds;
  int components = 0;  ///< how many connected components were merged
};

/// Segments one object frame by frame. Stateful (the background model, the last position), so one
/// segmenter per object, fed every frame in order.
class ObjectSegmenter {
 public:
  /// Throws std::invalid_argument for options out of range (negative sizes, fraction outside
  /// [0, 1], thresholds outside 0-255, HSV bounds outside their ranges).
  explicit ObjectSegmenter(const SegmenterOptions& options);

  const SegmenterOptions& options() const { return options_; }

  /// The object's blob in `bgr` (CV_8UC3), the video's frame number `frame_index`, or nullopt when
  /// it is not found there (no candidate pixels, nothing within the gate, smaller than the minimum
  /// area, or before background.start_frame). Throws std::invalid_argument for another image type,
  /// a frame size that changes between calls or a region of interest outside the frame.
  std::optional<Blob> segment(const cv::Mat& bgr, std::size_t frame_index);

  /// The candidate pixels of the last frame after morphology (CV_8UC1, 255 = candidate).
  const cv::Mat& candidate_mask() const { return candidates_; }
  /// The object's pixels of the last frame (CV_8UC1, 255 = object); all zero when not found.
  const cv::Mat& object_mask() const { return object_; }

 private:
  void make_candidates(const cv::Mat& bgr);
  /// The chosen component of the `count` labelled (0: none; label 0 is the background): in
  /// background tracking the nearest to the last centroid within the gate, else the largest.
  int choose_component(int count, bool tracking) const;
  /// The chosen component and the large fragments near it, drawn into object_, as a blob without
  /// its moments.
  Blob merge_fragments(int count, int anchor);
  int component_area(int label) const;
  cv::Rect component_box(int label) const;

  SegmenterOptions options_;
  cv::Ptr<cv::BackgroundSubtractorMOG2> background_;
  cv::Mat open_kernel_, close_kernel_;
  cv::Size frame_size_;
  std::optional<cv::Point2d> last_centroid_;
  cv::Mat scratch_, candidates_, object_, labels_, stats_, centroids_;
};

}  // namespace opf::vision
