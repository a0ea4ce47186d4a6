#include "opf/sim/scripted_scene.h"

#include "opf/core/so3.h"

#include <algorithm>
#include <stdexcept>

namespace opf::sim {
namespace {

// Deeper than any sensible chain of carriers; deeper means a cycle.
constexpr int kMaxCarryDepth = 16;

Eigen::Vector3d lerp(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double u) {
  return a + u * (b - a);
}

// Orientation of a sphere of `radius` rolling on a horizontal plane along the straight segment
// from a to b, starting at `start`: it turns by |d| / r about z x d (world frame).
Eigen::Quaterniond roll(const Eigen::Quaterniond& start, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b, double radius) {
  Eigen::Vector3d d = b - a;
  d.z() = 0.0;
  return (so3::exp(Eigen::Vector3d::UnitZ().cross(d) / radius) * start).normalized();
}

}  // namespace

ScriptedScene::ScriptedScene(std::vector<ScriptedBody> bodies)
    : bodies_(std::move(bodies)), driven_(bodies_.size()) {
  for (const ScriptedBody& b : bodies_) {
    if (b.waypoints.empty())
      throw std::invalid_argument("scripted scene: body '" + b.body.name + "' has no waypoints");
    for (std::size_t i = 1; i < b.waypoints.size(); ++i)
      if (!(b.waypoints[i].t > b.waypoints[i - 1].t))
        throw std::invalid_argument("scripted scene: waypoints of '" + b.body.name +
                                    "' are not in increasing time");
    for (const CarriedSpan& c : b.carried) {
      if (c.carrier == b.body.name)
        throw std::invalid_argument("scripted scene: '" + b.body.name + "' cannot carry itself");
      index_of(c.carrier);  // throws for an unknown carrier
      if (!(c.t_end > c.t_start))
        throw std::invalid_argument("scripted scene: carry of '" + b.body.name +
                                    "' must end after it starts");
    }
  }
  // Evaluating every body once at every carry boundary finds cycles now, not mid-experiment.
  for (const ScriptedBody& b : bodies_)
    for (const CarriedSpan& c : b.carried) pose_of(b.body.name, c.t_end);
}

std::size_t ScriptedScene::index_of(const std::string& name) const {
  for (std::size_t i = 0; i < bodies_.size(); ++i)
    if (bodies_[i].body.name == name) return i;
  throw std::invalid_argument("scripted scene: no body named '" + name + "'");
}

void ScriptedScene::drive(const std::string& name, const BodyPose& pose) {
  driven_[index_of(name)] = pose;
}

BodyPose ScriptedScene::pose_of(const std::string& name, double t) const {
  return pose_at(index_of(name), t, 0);
}

SceneSnapshot ScriptedScene::at(double t) const {
  SceneSnapshot snapshot;
  snapshot.t = t;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    snapshot.bodies.push_back(bodies_[i].body);
    snapshot.poses.push_back(pose_at(i, t, 0));
  }
  return snapshot;
}

BodyPose ScriptedScene::pose_at(std::size_t index, double t, int depth) const {
  if (depth > kMaxCarryDepth)
    throw std::invalid_argument("scripted scene: bodies carry each other in a cycle");
  if (driven_[index]) return *driven_[index];
  const ScriptedBody& b = bodies_[index];
  if (b.flight && t >= b.flight->t_start && t <= b.flight->t_end) {
    const double s = t - b.flight->t_start;
    return {b.flight->position + b.flight->velocity * s +
                Eigen::Vector3d(0, 0, -0.5 * b.flight->gravity * s * s),
            (so3::exp(b.flight->spin * s) * b.flight->orientation).normalized()};
  }
  for (const CarriedSpan& c : b.carried)
    if (t >= c.t_start && t < c.t_end) return carried_pose(index, c, t, depth);
  return scripted_pose(index, t, depth);
}

BodyPose ScriptedScene::carried_pose(std::size_t index, const CarriedSpan& span, double t,
                                     int depth) const {
  if (depth > kMaxCarryDepth)
    throw std::invalid_argument("scripted scene: bodies carry each other in a cycle");
  const std::size_t carrier = index_of(span.carrier);
  // Where the script had the body when the carry began (scripted_pose ignores carries still in
  // progress, so this is the pose it was picked up at).
  const BodyPose body0 = scripted_pose(index, span.t_start, depth + 1);
  const BodyPose carrier0 = pose_at(carrier, span.t_start, depth + 1);
  const BodyPose carrier_now = pose_at(carrier, t, depth + 1);
  const Eigen::Quaterniond turn = carrier_now.orientation * carrier0.orientation.conjugate();
  return {carrier_now.position + turn * (body0.position - carrier0.position),
          (turn * body0.orientation).normalized()};
}

BodyPose ScriptedScene::scripted_pose(std::size_t index, double t, int depth) const {
  const ScriptedBody& b = bodies_[index];
  // The timeline: the waypoints plus, at the end of each carry, where the carrier left the body.
  struct Key {
    double t;
    Eigen::Vector3d position;
    std::optional<Eigen::Quaterniond> orientation;
  };
  std::vector<Key> keys;
  for (const Waypoint& w : b.waypoints) keys.push_back({w.t, w.position, w.orientation});
  for (const CarriedSpan& c : b.carried) {
    if (c.t_end > t) continue;  // only carries already over shape the motion up to t
    const BodyPose left = carried_pose(index, c, c.t_end, depth + 1);
    keys.push_back({c.t_end, left.position, left.orientation});
  }
  std::stable_sort(keys.begin(), keys.end(), [](const Key& a, const Key& c) { return a.t < c.t; });
  // Drop waypoints that fall inside a carry already over: the carry decided that stretch.
  std::vector<Key> timeline;
  for (const Key& k : keys) {
    bool inside = false;
    for (const CarriedSpan& c : b.carried)
      if (c.t_end <= t && k.t >= c.t_start && k.t < c.t_end) inside = true;
    if (!inside) timeline.push_back(k);
  }

  const double radius = b.body.size.x();
  Eigen::Quaterniond orientation =
      timeline.front().orientation.value_or(Eigen::Quaterniond::Identity());
  if (t <= timeline.front().t) return {timeline.front().position, orientation};
  for (std::size_t i = 1; i < timeline.size(); ++i) {
    const Key& a = timeline[i - 1];
    const Key& c = timeline[i];
    if (a.orientation) orientation = *a.orientation;
    const double u = std::min(1.0, (t - a.t) / (c.t - a.t));
    const Eigen::Vector3d position = lerp(a.position, c.position, u);
    if (b.rolling) {
      if (t < c.t) return {position, roll(orientation, a.position, position, radius)};
      orientation = roll(orientation, a.position, c.position, radius);
      continue;
    }
    const Eigen::Quaterniond target = c.orientation.value_or(orientation);
    if (t < c.t) return {position, orientation.slerp(u, target).normalized()};
    orientation = target;
  }
  return {timeline.back().position, orientation};
}

}  // namespace opf::sim
