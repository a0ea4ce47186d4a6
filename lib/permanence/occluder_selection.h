#pragma once
// The occluder module's choice (paper Sec. III-B.2, Algorithm 1): which other object hides the
// static, unobserved object, by the Bhattacharyya distance between their position clouds, and
// whether two candidates are too close to call (then the OPF follows both).

#include "opf/core/enum_names.h"
#include "opf/core/option_schema.h"

#include <Eigen/Core>

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace opf {

/// Where the distances are measured. Occlusion happens along the camera's line of sight, so the
/// clouds are projected onto the plane perpendicular to the ray from the camera to the hidden
/// object (depth along the ray says nothing about who covers whom). kLineOfSight requires the
/// camera's position; kAuto (the default) takes it when given and a top-down camera otherwise
/// (the ray is -z: the paper's scenes), which `opf track` warns about for a log of several
/// objects.
enum class OccluderPlane { kAuto, kLineOfSight, kXY, k3D };
inline constexpr EnumNames<OccluderPlane, 4> kOccluderPlaneNames = {
    {{OccluderPlane::kAuto, "auto"},
     {OccluderPlane::kLineOfSight, "line_of_sight"},
     {OccluderPlane::kXY, "xy"},
     {OccluderPlane::k3D, "3d"}}};

struct OccluderOptions {
  /// m (paper Sec. III-B.2, "based on the size of the tested object"): without the gate (the
  /// paper's rule), two candidates tie when their distances from the hidden object across the
  /// line of sight differ by at most this.
  double epsilon_occ = 0.01;
  OccluderPlane plane = OccluderPlane::kAuto;
  /// The camera in the world frame, in homogeneous coordinates (core/homogeneous_point.h), for
  /// kLineOfSight and kAuto: (x, y, z, 1) a camera at that point; (x, y, z, 0) a camera
  /// infinitely far in the direction (x, y, z), every line of sight along -(x, y, z) (a log of
  /// `opf detect`, whose z is the depth away from the camera: (0, 0, -1, 0)). None (kAuto only):
  /// a camera straight above, as (0, 0, 1, 0): the line of sight is -z, the plane x-y, as in the
  /// paper's scenes.
  std::optional<Eigen::Vector4d> camera_position;
  /// Follow the occluder at the hidden object's offset from it at occlusion onset (the ball sits
  /// beside the mug's centre) instead of at the occluder's own position (the paper).
  bool keep_offset = false;
  /// Follow the occluder horizontally and keep the hidden object's own height: its vertical
  /// offset from the occluder at onset (vertical: the dynamics module's `up`). An object covered
  /// or carried from above lies under its occluder, not at its height: the mug under the hand
  /// hovering over it stays on the table (docs/occluder.md: sugar_drop 0.016 m against 0.023 m
  /// with the paper's rule). Along the camera's oblique ray instead it does worse on every
  /// bundled scene: a carried ball's offset from its cup is vertical, not along the ray. Implied
  /// by keep_offset. false: the paper's rule (the occluder's position is the hidden object's).
  bool keep_depth = true;
  /// Carry from the occluder's departure: a cup slid over a ball covers it before it carries it.
  /// An occluder at the object's level (within `reach` vertically) closes in: the hidden object
  /// is held where it was covered until the occluder has moved `departure_margin` (horizontally)
  /// from the place of its closest approach, and is then carried at its whole offset of that
  /// closest approach, turned with the occluder. An occluder above it (a hand, a lifted tray) is
  /// followed from onset by the keep_offset / keep_depth rule. false: carried from onset (the
  /// paper's rule).
  bool carry_from_departure = true;
  /// The carried orientation from the occluder's filtered estimate (a single detection's rotation
  /// noise would bias the whole carry). false: from its raw detections (the paper's y_k^j).
  bool orientation_from_estimate = true;
  /// m: above the jitter of a resting occluder's detection about its estimate (2 mm noise, and
  /// the estimate overshooting a few mm where a cup stops short), which would start the carry
  /// before a cup that paused beside the ball slides over it.
  double departure_margin = 0.01;
  /// The plausibility gate: a candidate can hide the object only if it is near it across the
  /// line of sight (within `reach` plus `gate_sigmas` standard deviations of the two estimates'
  /// combined spread) and not behind it (no more than `reach` further along the ray). Without
  /// it the nearest candidate is the occluder however far it is (the paper's rule): a static
  /// mug missed for one frame would follow a hand circling 0.3 m away. With no plausible
  /// candidate the hidden object is held where it was, its uncertainty growing. With it, every
  /// plausible candidate is a hypothesis weighted by how likely it hides the object
  /// (OccluderChoice::weighted), and the OPF keeps the object left in place as one more, all
  /// weighed each frame by what the camera does not see (place_visibility.h); without it, the
  /// nearest and the epsilon_occ tie.
  bool gate = true;
  /// m: the largest distance between the centres of an object and an occluder that hides it,
  /// across the line of sight: half their sizes summed. 0.15 m lets a 0.2 m tray or hand hide a
  /// ball or mug near its edge.
  double reach = 0.15;
  double gate_sigmas = 3.0;
};

/// The settings file's `opf.occluder:` section (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, OccluderOptions& o) {
  v.number("epsilon_occ", o.epsilon_occ, non_negative());
  v.choice("plane", kOccluderPlaneNames, o.plane);
  v.optional_point("camera_position", o.camera_position);
  v.flag("keep_depth", o.keep_depth);
  v.flag("carry_from_departure", o.carry_from_departure);
  v.flag("orientation_from_estimate", o.orientation_from_estimate);
  v.flag("gate", o.gate);
  v.number("reach", o.reach, non_negative("metres >= 0"));
  // keep_offset (an ablation of the carry), departure_margin (epsilon_occ's 1 cm) and
  // gate_sigmas (a 3-sigma gate) are set in code, not in settings.
}

/// A candidate occluder: another object's position estimate, and its size where stated.
struct OccluderCandidate {
  std::string object;
  Eigen::Vector3d mean;
  Eigen::Matrix3d covariance;
  /// m: its silhouette's radius as its detections state it; 0: not stated (`reach` is taken).
  double radius = 0.0;
};

/// A plausible occluder as a hypothesis: the candidate and the probability that it is the one
/// hiding the object.
struct WeightedOccluder {
  std::size_t candidate = 0;  ///< index into the candidates
  double probability = 0.0;
};

struct OccluderChoice {
  std::optional<std::size_t> nearest;  ///< index into the candidates
  std::size_t implausible = 0;         ///< candidates the gate turned away
  std::optional<std::size_t> second;   ///< set only when the choice is ambiguous
  double nearest_distance = 0.0;
  double second_distance = 0.0;  ///< of the runner-up, ambiguous or not (infinity if none)
  /// m between the centres across the line of sight (in 3-D for k3D): the tie's measure.
  double nearest_offset = 0.0;
  double second_offset = std::numeric_limits<double>::infinity();
  /// Every plausible candidate (options.gate) nearest first (by D_B), weighted by how plausibly it
  /// hides the object: the probability that its centre lies within `reach` of the object's across
  /// the line of sight, given both estimates' spread, to first order (the edge of that disc taken
  /// as straight where it is nearest the candidate: Phi((reach - |m|) / sigma), m the centres'
  /// offset and sigma its spread along m); normalised over the candidates, each equally likely
  /// before. Empty without the gate.
  std::vector<WeightedOccluder> weighted;
  bool ambiguous() const { return second.has_value(); }
};

/// The weighted candidates of at least `floor` probability, at most `max_count` of them (the most
/// probable; probabilities equal to 10^-6 nearest first), renormalised, most probable first.
std::vector<WeightedOccluder> probable_occluders(const OccluderChoice& choice, double floor,
                                                 std::size_t max_count);

/// Ranks the plausible candidates (options.gate) by D_B to the hidden object's cloud in the
/// configured plane. None: no occluder. One: it is the occluder. Otherwise the nearest is the
/// occluder when the two centres' distances from the hidden object's across the line of sight
/// differ by more than epsilon_occ (m); else both are returned. A
/// candidate whose estimate is not finite, or whose covariance is degenerate, is passed over.
OccluderChoice choose_occluders(const Eigen::Vector3d& hidden_mean,
                                const Eigen::Matrix3d& hidden_covariance,
                                std::span<const OccluderCandidate> candidates,
                                const OccluderOptions& options);

/// The unit direction from the camera towards the hidden object (top-down, -z, without a camera);
/// none for k3D.
std::optional<Eigen::Vector3d> line_of_sight(const Eigen::Vector3d& hidden_mean,
                                             const OccluderOptions& options);

/// The 2x3 (or 3x3 for k3D) projection onto the plane the distances are measured in.
Eigen::MatrixXd occlusion_plane_projection(const Eigen::Vector3d& hidden_mean,
                                           const OccluderOptions& options);

}  // namespace opf
