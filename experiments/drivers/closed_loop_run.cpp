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
#include <stdexcept>

namespace opf::experiments {
namespace {

const sim::Body& body_named(const sim::ScriptedScene& scene, const std::string& name) {
  return scene.bodies()[scene.index_of(name)].body;
}

}  // namespace

ExperimentResults run_closed_loop(const sim::ExperimentConfig& config,
                                  const std::vector<std::string>& estimators,
                                  const EstimatorSettings& settings, std::size_t seeds,
                                  std::uint64_t base_seed, const Progress& progress,
                                  std::size_t threads, std::size_t first_seed) {
  if (!config.closed_loop)
    throw std::invalid_argument("run_closed_loop: not a closed-loop experiment");
  const sim::ClosedLoopSettings& loop = *config.closed_loop;
  ExperimentResults results{config.name, estimators, seeds,      {},
                            {},          {},         first_seed, config.objects_of_interest};
  // One renderer for all runs: MRPT allows one off-screen renderer per process at a time.
  sim::CameraSensor sensor(camera_of(config));
  const double dt = 1.0 / config.rate;

  for (std::size_t s = first_seed; s < first_seed + seeds; ++s) {
    const std::uint64_t seed = derive_seed(base_seed, s);
    for (const std::string& name : estimators) {
      report_progress(progress, config, name, s - first_seed, seeds);
      sim::ScriptedScene scene(config.bodies);
      const sim::BodyPose robot_start = scene.pose_of(loop.robot, 0.0);
      const Eigen::Vector3d payload_offset =
          scene.pose_of(loop.payload, 0.0).position - robot_start.position;
      const sim::Body& target = body_named(scene, loop.target);
      const sim::Body& payload = body_named(scene, loop.payload);
      Eigen::Vector3d robot = robot_start.position;
      Eigen::Vector3d robot_velocity = Eigen::Vector3d::Zero();

      Random noise = measurement_noise(seed);
      Tracker tracker(make_estimator_factory(name, settings), seed, threads);
      ErrorAccumulator errors;
      DropOutcome drop;
      Eigen::Vector3d release_position = Eigen::Vector3d::Zero();
      bool tracking = false;
      std::optional<Eigen::Vector3d> previous_estimate;
      std::optional<double> nominal_trace;

      for (int k = 0; k < config.frames; ++k) {
        const double t = k * dt;
        scene.drive(loop.robot, {robot, robot_start.orientation});
        if (!drop.released) {
          scene.drive(loop.payload, {robot + payload_offset, Eigen::Quaterniond::Identity()});
        } else {
          // Falling: the payload keeps the robot's velocity at release, under gravity, until it
          // reaches the table.
          const double fall = t - drop.release_t;
          Eigen::Vector3d p = release_position + robot_velocity * fall;
          p.z() = std::max(payload.size.z() / 2.0,
                           release_position.z() - 0.5 * loop.gravity * fall * fall);
          scene.drive(loop.payload, {p, Eigen::Quaterniond::Identity()});
        }
        const sim::SceneSnapshot truth = scene.at(t);
        const Frame frame =
            sim::noisy_measurement(sensor.observe(truth), truth, config.measurement, noise);

        for (const Estimate& estimate : tracker.step(frame)) {
          const std::size_t index = scene.index_of(estimate.object);
          const sim::BodyPose& pose = truth.poses[index];
          if (config.is_of_interest(estimate.object))
            errors.add(estimate, make_pose(pose.position, pose.orientation));
          results.records.push_back(
              {k, name, s, pose, estimate, frame.find(estimate.object) != nullptr});
          if (estimate.object != loop.target) continue;

          // The controller acts on the estimate and its uncertainty, never on the truth.
          const Eigen::Vector3d estimated = translation_of(estimate.pose.mean);
          if (!nominal_trace) nominal_trace = estimate.observation_trace;
          const Eigen::Vector3d velocity =
              previous_estimate ? Eigen::Vector3d((estimated - *previous_estimate) / dt)
                                : Eigen::Vector3d::Zero();
          previous_estimate = estimated;
          if (!tracking && estimated.y() < loop.start_below_y) tracking = true;
          if (!tracking) continue;
          const Eigen::Vector3d goal = estimated + Eigen::Vector3d(0, 0, loop.hover_height);
          robot_velocity = cautious_velocity_command(robot, goal, velocity,
                                                     estimate.observation_trace, loop.controller);
          if (!drop.released && (robot - goal).head<2>().norm() < loop.release_distance &&
              estimate.observation_trace <= loop.release_trace_ratio * *nominal_trace) {
            drop.released = true;
            drop.release_t = t;
            release_position = robot + payload_offset;
            // Where it comes down: the rim's height, reached after the free fall.
            const double rim = pose.position.z() + target.size.z() / 2.0;
            const double height = std::max(0.0, release_position.z() - rim);
            const double fall = std::sqrt(2.0 * height / loop.gravity);
            const Eigen::Vector3d landing = release_position + robot_velocity * fall;
            const Eigen::Vector3d mug = scene.pose_of(loop.target, t + fall).position;
            drop.miss_distance = (landing - mug).head<2>().norm();
            drop.landed = drop.miss_distance < target.size.x() - payload.size.x() / 2.0;
          }
        }
        // Further hypotheses are recorded, not scored (the main hypothesis drives the robot).
        for (const Estimate& extra : tracker.hypotheses())
          results.records.push_back(
              {k, name, s, truth.poses[scene.index_of(extra.object)], extra, false});
        robot += robot_velocity * dt;
      }
      results.runs[name].push_back(errors.result());
      results.drops[name].push_back(drop);
    }
  }
  return results;
}

}  // namespace opf::experiments
