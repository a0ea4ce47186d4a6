#pragma once
// Runs an open-loop experiment: the scripted scene is rendered and detected once, then for every
// seed the sensor noise is drawn once and every estimator tracks that same stream, so comparisons
// between estimators are paired.

#include "opf/core/error_accumulator.h"
#include "opf/core/estimate.h"
#include "opf/core/frame.h"
#include "opf/core/random.h"
#include "opf/estimators/estimator_settings.h"
#include "opf/sim/experiment_config.h"
#include "opf/sim/sighting.h"

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace opf::experiments {

/// The scene's truth and what the camera saw, frame by frame.
struct Observation {
  std::vector<sim::SceneSnapshot> truth;
  std::vector<sim::CameraFrame> camera;
  /// A rendered frame for the figures: the middle of the longest stretch in which the first
  /// object of interest was unseen (what the estimators must reason about).
  int snapshot_frame = 0;
  cv::Mat snapshot_bgr;
};

/// One estimate of a tracked body at one frame, with its truth.
struct FrameRecord {
  int frame = 0;
  std::string estimator;
  std::size_t seed_index = 0;
  sim::BodyPose truth;
  Estimate estimate;
  bool visible = false;  ///< measured in this frame
};

/// What happened to the payload in one closed-loop run (sugar dropping).
struct DropOutcome {
  bool released = false;
  double release_t = 0.0;
  bool landed = false;         ///< inside the target's rim when it came down
  double miss_distance = 0.0;  ///< horizontal distance from the target's axis at landing, m
};

struct ExperimentResults {
  std::string experiment;
  std::vector<std::string> estimators;
  std::size_t seeds = 0;
  /// Per estimator, one RunErrors per seed over the objects of interest (mean over their frames).
  std::map<std::string, std::vector<RunErrors>> runs;
  std::vector<FrameRecord> records;  ///< every tracked body, estimator, seed and frame
  /// Closed-loop experiments only: per estimator, one outcome per seed.
  std::map<std::string, std::vector<DropOutcome>> drops;
  std::size_t first_seed = 0;  ///< the seed index of runs[...][0] (see run_open_loop)
  std::vector<std::string> objects_of_interest;  ///< the bodies `runs` are scored over
  /// The feedback module's threshold: the records' alert column is safety_alert at it, for every
  /// estimator's trace (results_to_fill takes the run's settings').
  double epsilon_safe = FeedbackOptions{}.epsilon_safe;
};

/// `settings` as an experiment runs them (`opf run`, `opf reproduce`, `opf sweep`): the occluder
/// module's line of sight starts at the experiment's camera unless the settings place one
/// themselves.
EstimatorSettings with_experiment_camera(EstimatorSettings settings,
                                         const sim::ExperimentConfig& config);

/// Called before each (estimator, seed) run: a line for the progress display.
using Progress = std::function<void(const std::string& line)>;

/// The sensor-noise generator of the run with seed `run_seed`: independent of the filters' own
/// generators (derived from the same seed), and the same for every estimator of that seed.
Random measurement_noise(std::uint64_t run_seed);

/// The results of a run before any estimator ran: what runs, over which seeds, and the threshold
/// of its alert column (the feedback module's epsilon_safe in `settings`).
ExperimentResults results_to_fill(const sim::ExperimentConfig& config,
                                  const std::vector<std::string>& estimators, std::size_t seeds,
                                  std::size_t first_seed, const EstimatorSettings& settings);

/// Reports "<experiment>: <estimator>, seed k/n" when `progress` is set.
void report_progress(const Progress& progress, const sim::ExperimentConfig& config,
                     const std::string& estimator, std::size_t seed_index, std::size_t seeds);

/// What the camera measured in the run of seed index `seed_index` (run seed
/// derive_seed(base_seed, seed_index)): a frame per camera frame, with that seed's sensor noise.
/// Every estimator of that run tracks these frames.
std::vector<Frame> measurement_stream(const sim::ExperimentConfig& config,
                                      const Observation& observation, std::uint64_t base_seed,
                                      std::size_t seed_index);

/// Runs seed indices first_seed .. first_seed + seeds - 1, each with run seed
/// derive_seed(base_seed, index): a part of a longer run reproduces its seeds exactly (sweeps
/// run one seed per process). Records carry the seed index. Throws std::invalid_argument for an
/// unknown estimator (the registry's message).
ExperimentResults run_open_loop(const sim::ExperimentConfig& config, const Observation& observation,
                                const std::vector<std::string>& estimators,
                                const EstimatorSettings& settings, std::size_t seeds,
                                std::uint64_t base_seed, const Progress& progress = {},
                                std::size_t threads = 1, std::size_t first_seed = 0);

}  // namespace opf::experiments
