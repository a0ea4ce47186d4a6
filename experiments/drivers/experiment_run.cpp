#include "drivers/experiment_run.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/tracker.h"
#include "opf/estimators/registry.h"
#include "opf/sim/noisy_measurement.h"

#include <algorithm>
#include <stdexcept>

namespace opf::experiments {

EstimatorSettings with_experiment_camera(EstimatorSettings settings,
                                         const sim::ExperimentConfig& config) {
  if (!settings.opf.occluder.camera_position)
    settings.opf.occluder.camera_position = config.camera.position.homogeneous();
  return settings;
}

Random measurement_noise(std::uint64_t run_seed) {
  return Random(derive_seed(run_seed, 0x6e6f697365));  // "noise"
}

ExperimentResults results_to_fill(const sim::ExperimentConfig& config,
                                  const std::vector<std::string>& estimators, std::size_t seeds,
                                  std::size_t first_seed, const EstimatorSettings& settings) {
  ExperimentResults results;
  results.experiment = config.name;
  results.estimators = estimators;
  results.seeds = seeds;
  results.first_seed = first_seed;
  results.objects_of_interest = config.objects_of_interest;
  results.epsilon_safe = settings.opf.feedback.epsilon_safe;
  return results;
}

void report_progress(const Progress& progress, const sim::ExperimentConfig& config,
                     const std::string& estimator, std::size_t seed_index, std::size_t seeds) {
  if (progress)
    progress(config.name + ": " + estimator + ", seed " + std::to_string(seed_index + 1) + "/" +
             std::to_string(seeds));
}

std::vector<Frame> measurement_stream(const sim::ExperimentConfig& config,
                                      const Observation& observation, std::uint64_t base_seed,
                                      std::size_t seed_index) {
  if (observation.truth.size() != observation.camera.size())
    throw std::invalid_argument("measurement_stream: truth and camera frames differ in number");
  Random noise = measurement_noise(derive_seed(base_seed, seed_index));
  std::vector<Frame> frames;
  for (std::size_t k = 0; k < observation.camera.size(); ++k)
    frames.push_back(sim::noisy_measurement(observation.camera[k], observation.truth[k],
                                            config.measurement, noise));
  return frames;
}

ExperimentResults run_open_loop(const sim::ExperimentConfig& config, const Observation& observation,
                                const std::vector<std::string>& estimators,
                                const EstimatorSettings& settings, std::size_t seeds,
                                std::uint64_t base_seed, const Progress& progress,
                                std::size_t threads, std::size_t first_seed) {
  if (observation.truth.size() != observation.camera.size())
    throw std::invalid_argument("run_open_loop: truth and camera frames differ in number");
  ExperimentResults results = results_to_fill(config, estimators, seeds, first_seed, settings);

  for (std::size_t s = first_seed; s < first_seed + seeds; ++s) {
    // The seed's measurement stream, shared by every estimator (paired comparison).
    const std::uint64_t seed = derive_seed(base_seed, s);
    const std::vector<Frame> frames = measurement_stream(config, observation, base_seed, s);

    for (const std::string& name : estimators) {
      report_progress(progress, config, name, s - first_seed, seeds);
      Tracker tracker(make_estimator_factory(name, settings), seed, threads);
      ErrorAccumulator errors(results.epsilon_safe);
      for (std::size_t k = 0; k < frames.size(); ++k) {
        const sim::SceneSnapshot& truth = observation.truth[k];
        const auto truth_of = [&](const std::string& object) -> const sim::BodyPose& {
          for (std::size_t i = 0; i < truth.bodies.size(); ++i)
            if (truth.bodies[i].name == object) return truth.poses[i];
          throw std::logic_error("run_open_loop: estimate of an unknown body " + object);
        };
        for (const Estimate& estimate : tracker.step(frames[k])) {
          const sim::BodyPose& pose = truth_of(estimate.object);
          if (config.is_of_interest(estimate.object))
            errors.add(estimate, make_pose(pose.position, pose.orientation));
          results.records.push_back({static_cast<int>(k), name, s, pose, estimate,
                                     frames[k].find(estimate.object) != nullptr});
        }
        // Further hypotheses (two equally likely occluders) are recorded, not scored: the
        // error is the main hypothesis's, as the tracker reports it.
        for (const Estimate& extra : tracker.hypotheses()) {
          results.records.push_back(
              {static_cast<int>(k), name, s, truth_of(extra.object), extra, false});
        }
      }
      results.runs[name].push_back(errors.result());
    }
  }
  return results;
}

}  // namespace opf::experiments
