#pragma once
// A pose from a 2-D blob, for measurement logs made from a single uncalibrated video: the centroid
// at a nominal scale gives x and y, the apparent size gives the depth, the principal axis of the
// image moments gives a rotation about the optical (z) axis.
//
//   x = u * metres_per_pixel, y = v * metres_per_pixel      (pixel centroid; default 1 px = 1 mm)
//   z = reference_depth * sqrt(reference_area / area)       (area ~ 1 / z^2 under perspective)
//   angle = 0.5 * atan2(2 mu11, mu20 - mu02), unwrapped by multiples of pi along the sequence
//
// The principal axis is a line, not a direction, so its angle is only defined up to pi: without
// unwrapping, an object turning through +-pi/2 would appear to flip by half a turn.

#include <opencv2/core/types.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace opf::vision {

struct BlobPoseOptions {
  double metres_per_pixel = 0.001;
  double reference_depth = 1.0;  ///< metres, the depth at which the blob has reference_area
  /// Pixels; when unset, the median area of the first reference_frames sightings.
  std::optional<double> reference_area;
  std::size_t reference_frames = 5;
};

/// One detection of a blob: what the pose is computed from.
struct BlobSighting {
  std::size_t frame = 0;  ///< video frame number
  cv::Point2d centroid_px;
  double area_px = 0.0;
  double axis_angle = 0.0;  ///< principal_axis_angle of its moments
};

struct BlobPose {
  std::size_t frame = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double angle = 0.0;  ///< unwrapped rotation about z, radians
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< about z by angle, w >= 0
};

/// The angle of the principal axis of the central moments, in [-pi/2, pi/2]: 0 along +u, pi/2
/// along +v (the image's y axis, downwards). Arbitrary (0) for a blob with no elongation.
double principal_axis_angle(const cv::Moments& moments);

/// `angle` plus the multiple of pi that brings it nearest to `previous`.
double unwrap_half_turn(double angle, double previous);

/// The median area of the first `count` sightings (all of them when fewer); throws
/// std::invalid_argument when there are none or count is 0.
double median_reference_area(std::span<const BlobSighting> sightings, std::size_t count);

/// The poses of one object's sightings, in their order (increasing frame): the angles unwrapped
/// from one sighting to the next. Throws std::invalid_argument for non-positive scale, depth,
/// reference area or a sighting's area.
std::vector<BlobPose> blob_poses(std::span<const BlobSighting> sightings,
                                 const BlobPoseOptions& options);

}  // namespace opf::vision
