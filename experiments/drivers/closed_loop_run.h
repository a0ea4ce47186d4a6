#pragma once
// Runs a closed-loop experiment (paper experiment 2, sugar dropping): the robot's end-effector
// follows the estimator's estimate of the target through the cautious tracking controller, so
// the estimator's quality changes the scene it sees (the robot occludes the target itself), and
// it releases its payload when the uncertainty is low over the target.

#include "drivers/experiment_run.h"

namespace opf::experiments {

/// Renders every frame of every (estimator, seed) run, since the robot's motion depends on the
/// estimates. Requires config.closed_loop. The frame errors are those of the objects of interest.
/// Seeds as in run_open_loop.
ExperimentResults run_closed_loop(const sim::ExperimentConfig& config,
                                  const std::vector<std::string>& estimators,
                                  const EstimatorSettings& settings, std::size_t seeds,
                                  std::uint64_t base_seed, const Progress& progress = {},
                                  std::size_t threads = 1, std::size_t first_seed = 0);

}  // namespace opf::experiments
