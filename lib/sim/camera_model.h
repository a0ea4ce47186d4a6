#pragma once
// The simulator's pinhole camera: intrinsics in pixels and the camera's pose in the world, shared
// by the renderer (what the image shows), the blob detector (pixel -> world) and the silhouettes.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>

namespace opf::sim {

/// What keeps CameraModel::look_at from placing a camera: the target at the eye, or an `up` along
/// the line of sight (no roll follows from it).
enum class LookAtFault { kNone, kTargetAtEye, kUpAlongView };
LookAtFault look_at_fault(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                          const Eigen::Vector3d& up);

/// OpenCV conventions throughout. Camera frame: x right, y down, z forward (the optical axis).
/// Pixels: (u, v) = (column, row); integer coordinates are pixel CENTRES, so pixel (0, 0) covers
/// [-0.5, 0.5]^2 and the image spans [-0.5, width - 0.5] x [-0.5, height - 0.5]. Depth is z-depth
/// (the camera-frame z of a point), not the range along the ray. Undistorted, square pixels.
struct CameraModel {
  static constexpr int kDefaultWidth = 640;
  static constexpr int kDefaultHeight = 480;
  /// 75 degrees vertical (about 91 degrees horizontal at 4:3). The sugar-dropping camera, 0.8 m
  /// above the table, must see the mug from y = +0.45 to -0.45 m plus its radius along the
  /// image's long side: tan(h/2) >= 0.5 / 0.7 gives h >= 71 degrees, i.e. a vertical FOV >= 56.
  /// The general-tracking camera, only 0.49 m up, must see x from 0.3 to 0.8 m (the mug at
  /// x = 0.8 with its top ~0.4 m from the lens) along the short side: tan(v/2) >= 0.29 / 0.41,
  /// v >= 70 degrees. 75 covers both with a margin and still gives a 2.5 cm ball ~300 pixels at
  /// 0.8 m.
  static constexpr double kDefaultVerticalFovRad = 75.0 * 3.14159265358979323846 / 180.0;

  int width = kDefaultWidth;
  int height = kDefaultHeight;
  /// Focal lengths and principal point in pixels; the defaults come from kDefaultVerticalFovRad
  /// with the principal point at the image centre ((width - 1) / 2, (height - 1) / 2).
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  /// Maps camera-frame coordinates to world coordinates (its translation is the optical centre).
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();

  /// 640 x 480, kDefaultVerticalFovRad, at the world origin looking along world +z.
  CameraModel();

  /// A camera at `eye` whose optical axis passes through `target`, rolled so that `up` points
  /// up in the image (towards row 0). Square pixels; principal point at the image centre.
  /// Throws std::invalid_argument if eye == target, `up` is parallel to the view direction, the
  /// FOV is not in (0, pi) or the size is not positive.
  static CameraModel look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                             const Eigen::Vector3d& up,
                             double vertical_fov_rad = kDefaultVerticalFovRad,
                             int width = kDefaultWidth, int height = kDefaultHeight);

  /// The paper's cameras: at `eye`, looking straight down (world -z), with world +x (away from
  /// the robot base) up in the image. Then world -y is image right and world +y image left, so
  /// the paper's "left" mug (y = +0.15) is on the left, and the robot base (x = 0) is at the
  /// bottom edge, as seen standing behind the robot.
  static CameraModel top_down(const Eigen::Vector3d& eye,
                              double vertical_fov_rad = kDefaultVerticalFovRad,
                              int width = kDefaultWidth, int height = kDefaultHeight);

  double vertical_fov_rad() const;
  /// World position of the optical centre and the unit optical axis (camera +z) in the world.
  Eigen::Vector3d position() const { return world_from_camera.translation(); }
  Eigen::Vector3d forward() const { return world_from_camera.linear().col(2); }

  Eigen::Vector3d to_camera(const Eigen::Vector3d& world) const;

  /// The pixel where `world` appears, and its z-depth in `depth` if given; nullopt when the point
  /// is not strictly in front of the camera (z <= 0). The pixel may lie outside the image: check
  /// with in_image().
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& world,
                                         double* depth = nullptr) const;

  /// The world point on the ray through `pixel` whose z-depth is `z_depth` (metres).
  Eigen::Vector3d back_project(const Eigen::Vector2d& pixel, double z_depth) const;

  bool in_image(const Eigen::Vector2d& pixel) const;
};

}  // namespace opf::sim
