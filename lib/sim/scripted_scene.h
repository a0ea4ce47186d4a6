#pragma once
// A scene whose bodies move by script: piecewise-linear waypoints with timing, spans during which
// a body is carried by another (the ball under the mug), rolling without slipping, and poses set
// from outside (the robot's end-effector under the controller). at(t) gives the snapshot.

#include "opf/sim/body.h"

#include <optional>
#include <string>
#include <vector>

namespace opf::sim {

struct Waypoint {
  double t = 0.0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// Absent: keep the orientation the body had (or the rolling orientation).
  std::optional<Eigen::Quaterniond> orientation;
};

/// From t_start to t_end the body moves rigidly with `carrier`, at the offset it had from the
/// carrier at t_start. Afterwards it stays where the carrier left it until its next waypoint.
struct CarriedSpan {
  double t_start = 0.0;
  double t_end = 0.0;
  std::string carrier;
};

struct ScriptedBody {
  Body body;
  /// Sorted by time; before the first the body rests at the first, after the last at the last.
  std::vector<Waypoint> waypoints;
  std::vector<CarriedSpan> carried;
  /// A sphere rolling on the table: its orientation turns with the distance travelled
  /// (angle = distance / radius about z x direction), instead of following the waypoints.
  bool rolling = false;
  /// A throw: from t_start to t_end the body flies from `position` with `velocity` under gravity
  /// (-z) and spins at `spin` (rad/s, world frame) from `orientation`; outside it, the waypoints.
  struct Flight {
    double t_start = 0.0;
    double t_end = 0.0;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
    Eigen::Vector3d spin = Eigen::Vector3d::Zero();
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    double gravity = 9.81;
  };
  std::optional<Flight> flight;
};

class ScriptedScene {
 public:
  /// Throws std::invalid_argument for unsorted waypoints, a body without waypoints, an unknown
  /// or self carrier, or a carry cycle.
  explicit ScriptedScene(std::vector<ScriptedBody> bodies);

  /// Every body's pose at time t.
  SceneSnapshot at(double t) const;
  BodyPose pose_of(const std::string& name, double t) const;

  /// Puts `name` at `pose` from now on, overriding its script (a body driven from outside).
  void drive(const std::string& name, const BodyPose& pose);

  const std::vector<ScriptedBody>& bodies() const { return bodies_; }
  std::size_t index_of(const std::string& name) const;

 private:
  BodyPose pose_at(std::size_t index, double t, int depth) const;
  BodyPose scripted_pose(std::size_t index, double t, int depth) const;
  BodyPose carried_pose(std::size_t index, const CarriedSpan& span, double t, int depth) const;

  std::vector<ScriptedBody> bodies_;
  std::vector<std::optional<BodyPose>> driven_;
};

}  // namespace opf::sim
