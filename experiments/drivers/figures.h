#pragma once
// The figures of an experiment, in the manner of the paper's Fig. 3: per object of interest the
// translation and rotation error over time per estimator and the trace of Q~ with the alert's
// threshold, hidden frames shaded; a rendered snapshot with every estimator's estimate drawn in.
// PNG, from the first seed.

#include "drivers/experiment_run.h"
#include "opf/sim/experiment_config.h"

#include <filesystem>
#include <vector>

namespace opf::experiments {

/// Writes <experiment>_<object>_{translation_error,rotation_error,trace}.png and
/// <experiment>_snapshot.png into `dir`; returns the paths written. `epsilon_safe` is the
/// feedback module's alert threshold on trace(Q~), drawn on the trace figure.
std::vector<std::filesystem::path> write_figures(const std::filesystem::path& dir,
                                                 const sim::ExperimentConfig& config,
                                                 const Observation& observation,
                                                 const ExperimentResults& results,
                                                 double epsilon_safe);

}  // namespace opf::experiments
