#include "drivers/closed_loop_run.h"

#include "drivers/observe_experiment.h"
#include "opf/control/cautious_tracking_controller.h"
#include "opf/core/pose_conversion.h"
#include "opf/core/tracker.h"
#include "opf/estimators/registry.h"
#include "opf/sim/camera_sensor.h"
#include "opf/sim/noisy_measurement.h"
#include "opf/sim/scripted_scene.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

namespace opf::experiments {
namespace {

const sim::Body& body_named(const sim::ScriptedScene& scene, const std::string& name) {
  return scene.bodies()[scene.index_of(name)].body;
}

// One run of the loop: the robot carries the payload towards where the target is estimated, by
// the cautious controller, and releases it over the target once the uncertainty is low; the
// payload then falls with the robot's velocity at release until it reaches the table.
class Episode {
 public:
  Episode(const sim::ClosedLoopSettings& loop, sim::ScriptedScene& scene)
      : loop_(loop),
        scene_(scene),
        robot_start_(scene.pose_of(loop.robot, 0.0)),
        payload_offset_(scene.pose_of(loop.payload, 0.0).position - robot_start_.position),
        target_(body_named(scene, loop.target)),
        payload_(body_named(scene, loop.payload)),
        robot_(robot_start_.position) {}

  /// Places the robot, and the payload it holds or that falls, at t.
  void move_bodies(double t) {
    scene_.drive(loop_.robot, {robot_, robot_start_.orientation});
    if (!drop_.released) {
      scene_.drive(loop_.payload, {robot_ + payload_offset_, Eigen::Quaterniond::Identity()});
      return;
    }
    const double fall = t - drop_.release_t;
    Eigen::Vector3d p = release_position_ + robot_velocity_ * fall;
    p.z() = std::max(payload_.size.z() / 2.0,
                     release_position_.z() - 0.5 * loop_.gravity * fall * fall);
    scene_.drive(loop_.payload, {p, Eigen::Quaterniond::Identity()});
  }

  /// The controller's command from the target's estimate and its uncertainty (never the truth),
  /// and the release when the robot is over it and sure enough. `target_truth` only scores where
  /// the payload lands.
  void act_on(const Estimate& estimate, const sim::BodyPose& target_truth, double t, double dt) {
    const Eigen::Vector3d estimated = translation_of(estimate.pose.mean);
    if (!nominal_trace_) nominal_trace_ = estimate.observation_trace;
    const Eigen::Vector3d velocity = previous_estimate_
                                         ? Eigen::Vector3d((estimated - *previous_estimate_) / dt)
                                         : Eigen::Vector3d::Zero();
    previous_estimate_ = estimated;
    if (!tracking_ && estimated.y() < loop_.start_below_y) tracking_ = true;
    if (!tracking_) return;
    const Eigen::Vector3d goal = estimated + Eigen::Vector3d(0, 0, loop_.hover_height);
    robot_velocity_ = cautious_velocity_command(robot_, goal, velocity, estimate.observation_trace,
                                                loop_.controller);
    if (!drop_.released && (robot_ - goal).head<2>().norm() < loop_.release_distance &&
        estimate.observation_trace <= loop_.release_trace_ratio * *nominal_trace_)
      release(target_truth, t);
  }

  /// The robot moves by its last command.
  void advance(double dt) { robot_ += robot_velocity_ * dt; }

  const DropOutcome& drop() const { return drop_; }

 private:
  void release(const sim::BodyPose& target_truth, double t) {
    drop_.released = true;
    drop_.release_t = t;
    release_position_ = robot_ + payload_offset_;
    // Where it comes down: the rim's height, reached after the free fall.
    const double rim = target_truth.position.z() + target_.size.z() / 2.0;
    const double height = std::max(0.0, release_position_.z() - rim);
    const double fall = std::sqrt(2.0 * height / loop_.gravity);
    const Eigen::Vector3d landing = release_position_ + robot_velocity_ * fall;
    const Eigen::Vector3d mug = scene_.pose_of(loop_.target, t + fall).position;
    drop_.miss_distance = (landing - mug).head<2>().norm();
    drop_.landed = drop_.miss_distance < target_.size.x() - payload_.size.x() / 2.0;
  }

  const sim::ClosedLoopSettings& loop_;
  sim::ScriptedScene& scene_;
  const sim::BodyPose robot_start_;
  const Eigen::Vector3d payload_offset_;
  const sim::Body& target_;
  const sim::Body& payload_;
  Eigen::Vector3d robot_;
  Eigen::Vector3d robot_velocity_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d release_position_ = Eigen::Vector3d::Zero();
  DropOutcome drop_;
  bool tracking_ = false;
  std::optional<Eigen::Vector3d> previous_estimate_;
  std::optional<double> nominal_trace_;
};

}  // namespace

ExperimentResults run_closed_loop(const sim::ExperimentConfig& config,
                                  const std::vector<std::string>& estimators,
                                  const EstimatorSettings& settings, std::size_t seeds,
                                  std::uint64_t base_seed, const Progress& progress,
                                  std::size_t threads, std::size_t first_seed) {
  if (!config.closed_loop)
    throw std::invalid_argument("run_closed_loop: not a closed-loop experiment");
  const sim::ClosedLoopSettings& loop = *config.closed_loop;
  ExperimentResults results = results_to_fill(config, estimators, seeds, first_seed, settings);
  // One renderer for all runs: MRPT allows one off-screen renderer per process at a time.
  sim::CameraSensor sensor(camera_of(config), {}, detection_of(config));
  const double dt = 1.0 / config.rate;

  for (std::size_t s = first_seed; s < first_seed + seeds; ++s) {
    const std::uint64_t seed = derive_seed(base_seed, s);
    for (const std::string& name : estimators) {
      report_progress(progress, config, name, s - first_seed, seeds);
      sim::ScriptedScene scene(config.bodies);
      Episode episode(loop, scene);
      Random noise = measurement_noise(seed);
      Tracker tracker(make_estimator_factory(name, settings), seed, threads);
      ErrorAccumulator errors(results.epsilon_safe);
      std::set<std::string> estimated;  // the objects of interest the run has estimated
      for (int k = 0; k < config.frames; ++k) {
        const double t = k * dt;
        episode.move_bodies(t);
        const sim::SceneSnapshot truth = scene.at(t);
        const Frame frame =
            sim::noisy_measurement(sensor.observe(truth), truth, config.measurement, noise);
        for (const Estimate& estimate : tracker.step(frame)) {
          const sim::BodyPose& pose = truth.poses[scene.index_of(estimate.object)];
          if (config.is_of_interest(estimate.object)) {
            errors.add(estimate, make_pose(pose.position, pose.orientation));
            estimated.insert(estimate.object);
          }
          results.records.push_back(
              {k, name, s, pose, estimate, frame.find(estimate.object) != nullptr});
          if (estimate.object == loop.target) episode.act_on(estimate, pose, t, dt);
        }
        // Further hypotheses are recorded, not scored (the main hypothesis drives the robot).
        for (const Estimate& extra : tracker.hypotheses())
          results.records.push_back(
              {k, name, s, truth.poses[scene.index_of(extra.object)], extra, false});
        episode.advance(dt);
      }
      // What the camera sees depends on the robot, so the check comes after the run.
      for (const std::string& object : config.objects_of_interest)
        if (!estimated.contains(object))
          refuse_unseen_object(config, object, static_cast<std::size_t>(config.frames));
      results.runs[name].push_back(errors.result());
      results.drops[name].push_back(episode.drop());
    }
  }
  return results;
}

}  // namespace opf::experiments
