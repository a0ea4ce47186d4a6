#pragma once
// The occluder module's choice (paper Sec. III-B.2, Algorithm 1): which other object hides the
// static, unobserved object, by the Bhattacharyya distance between their position clouds, and
// whether two candidates are too close to call (then the OPF follows both).

#include <Eigen/Core>

#include <optional>
#include <span>
#include <string>

namespace opf {

/// Where the distances are measured. Occlusion happens along the camera's line of sight, so by
/// default the clouds are projected onto the plane perpendicular to the ray from the camera to
/// the hidden object (depth along the ray says nothing about who covers whom).
enum class OccluderPlane { kLineOfSight, kXY, k3D };

struct OccluderOptions {
  double epsilon_occ = 0.01;  ///< paper Sec. III-B.2: D_B gap below which two occluders tie
  OccluderPlane plane = OccluderPlane::kLineOfSight;
  /// Camera position in the world frame for kLineOfSight; none means a top-down camera (the
  /// line of sight is -z, the plane is x-y), as in the paper's scenes.
  std::optional<Eigen::Vector3d> camera_position;
  /// Follow the occluder at the hidden object's offset from it at occlusion onset (the ball sits
  /// beside the mug's centre) instead of at the occluder's own position (the paper).
  bool keep_offset = false;
  /// Follow the occluder only across the line of sight and keep the hidden object's own offset
  /// from it along the ray (from onset): an occluder says where the object is across the ray,
  /// not how deep along it, which is what occlusion hides. The ball under a hand hovering over its
  /// cup then stays on the table, not at the hand's height. Implied by keep_offset; no effect
  /// with plane k3D, which has no line of sight.
  bool keep_depth = false;
};

/// A candidate occluder: another object's position estimate.
struct OccluderCandidate {
  std::string object;
  Eigen::Vector3d mean;
  Eigen::Matrix3d covariance;
};

struct OccluderChoice {
  std::optional<std::size_t> nearest;  ///< index into the candidates
  std::optional<std::size_t> second;   ///< set only when the choice is ambiguous
  double nearest_distance = 0.0;
  double second_distance = 0.0;  ///< of the runner-up, ambiguous or not (infinity if none)
  bool ambiguous() const { return second.has_value(); }
};

/// Ranks the candidates by D_B to the hidden object's cloud in the configured plane. No
/// candidates: no occluder. One candidate: it is the occluder. Otherwise the nearest is the
/// occluder when the runner-up is more than epsilon_occ further; else both are returned.
OccluderChoice choose_occluders(const Eigen::Vector3d& hidden_mean,
                                const Eigen::Matrix3d& hidden_covariance,
                                std::span<const OccluderCandidate> candidates,
                                const OccluderOptions& options);

/// The 2x3 (or 3x3 for k3D) projection onto the plane the distances are measured in.
Eigen::MatrixXd occlusion_plane_projection(const Eigen::Vector3d& hidden_mean,
                                           const OccluderOptions& options);

}  // namespace opf
