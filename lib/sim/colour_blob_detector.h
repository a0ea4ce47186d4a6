#pragma once
// The paper's measurement (Sec. IV-B): colour segmentation and blob detection on the rendered
// image, giving each tracked body's pixel centroid, pixel area and a 3-D point from the depth.

#include <opencv2/core/mat.hpp>

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "opf/sim/body.h"
#include "opf/sim/camera_model.h"

namespace opf::sim {

/// Recommended body colours: six fully saturated hues 60 degrees apart, so that with the default
/// hue tolerance (+-10 degrees) no detector ever accepts another body's pixels, and the shading
/// (which scales the value only) never moves a pixel's hue. Bodies that are not tracked (table,
/// robot links) should be unsaturated (HSV saturation < ColourBlobDetectorOptions::
/// min_saturation), like kTable. The end-effector has a hue of its own even though it is not
/// tracked, so that it can be segmented too (e.g. to measure self-occlusion) without ever being
/// mistaken for a tracked body.
namespace palette {
inline constexpr Colour kBall{255, 0, 0};           // red, hue 0
inline constexpr Colour kTray{255, 255, 0};         // yellow, hue 60
inline constexpr Colour kLeftMug{0, 255, 0};        // green, hue 120
inline constexpr Colour kEndEffector{0, 255, 255};  // cyan, hue 180
inline constexpr Colour kRightMug{0, 0, 255};       // blue, hue 240
inline constexpr Colour kCup{255, 0, 255};          // magenta, hue 300 (sugar-dropping mug)
inline constexpr Colour kTable{150, 150, 150};      // grey, saturation 0
}  // namespace palette

struct ColourBlobDetectorOptions {
  /// Half-width of the accepted hue band around the body colour's hue, in degrees. 10 tolerates
  /// 8-bit rounding on shaded pixels and keeps the palette's hues (60 apart) far from each other.
  double hue_tolerance_deg = 10.0;
  /// Minimum HSV saturation, 0-255: rejects grey table, robot and background pixels.
  int min_saturation = 100;
  /// Minimum HSV value, 0-255. The renderer's shading never darkens a colour below 0.6 of its
  /// value, so a palette colour (value 255) stays >= 153; 60 rejects near-black pixels whose hue
  /// is noise.
  int min_value = 60;
  /// A largest blob smaller than this many pixels counts as no detection (the body is missing).
  int min_area_pixels = 30;
};

struct BlobMeasurement {
  /// Centroid of the blob's pixels (OpenCV pixel-centre convention, see CameraModel).
  Eigen::Vector2d centroid_px = Eigen::Vector2d::Zero();
  double area_px = 0.0;
  /// Median z-depth of the blob's pixels with a depth return, metres.
  double depth_m = 0.0;
  /// The centroid back-projected to depth_m: a point on the VISIBLE SURFACE, not the body's
  /// centre. The detector does not know the body's shape, so like a real RGB-D sensor it reports
  /// a biased point: for a fully visible sphere seen from above it lies ~0.7 r towards the camera
  /// from the centre (the median depth over a disc), and a partly covered body gives a centroid
  /// shifted towards its visible part.
  Eigen::Vector3d surface_point_world = Eigen::Vector3d::Zero();
};

/// Whether the detector can segment `colour` at all: its HSV saturation and value reach the
/// minimums (a grey or black body has no hue to find).
bool segmentable(const Colour& colour, const ColourBlobDetectorOptions& options = {});

/// Whether the detector of `tracked` would take pixels of a body of colour `other` for it:
/// `other` is segmentable and the hue bands of the two (each +- hue_tolerance_deg) overlap.
bool confusable(const Colour& tracked, const Colour& other,
                const ColourBlobDetectorOptions& options = {});

/// Segments one colour: pixels whose hue is within the tolerance of the colour's hue and whose
/// saturation and value pass the minimums, 8-connected components, the largest one kept.
/// Holds scratch images between calls (so it is cheap per frame and not thread-safe).
class ColourBlobDetector {
 public:
  /// Throws std::invalid_argument for a tolerance outside [0, 90) degrees or negative minimums.
  explicit ColourBlobDetector(const ColourBlobDetectorOptions& options = {});

  const ColourBlobDetectorOptions& options() const { return options_; }

  /// The largest blob of `colour` in a BGR image (CV_8UC3) with its CV_32FC1 z-depth image (0 =
  /// no return), or nullopt when it is smaller than min_area_pixels or has no depth return.
  /// Throws std::invalid_argument if the images do not match or `colour` is too unsaturated to
  /// ever pass min_saturation.
  std::optional<BlobMeasurement> detect(const cv::Mat& bgr, const cv::Mat& depth,
                                        const Colour& colour, const CameraModel& camera);

  /// One entry per body (result[i] for bodies[i]); untracked bodies always get nullopt. Converts
  /// the image to HSV once for all bodies.
  std::vector<std::optional<BlobMeasurement>> detect_tracked(const cv::Mat& bgr,
                                                             const cv::Mat& depth,
                                                             const std::vector<Body>& bodies,
                                                             const CameraModel& camera);

 private:
  void convert(const cv::Mat& bgr, const cv::Mat& depth);
  std::optional<BlobMeasurement> detect_in_hsv(const cv::Mat& depth, const Colour& colour,
                                               const CameraModel& camera);

  ColourBlobDetectorOptions options_;
  cv::Mat hsv_, mask_, wrap_mask_, labels_, stats_, centroids_;
  std::vector<float> depths_;
};

}  // namespace opf::sim
