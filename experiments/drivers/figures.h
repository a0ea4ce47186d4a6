#pragma once
// The figures of an experiment, in the manner of the paper's Fig. 3: per object of interest the
// translation and rotation error over time per estimator and the trace of Q~ with the alert's
// threshold, hidden frames shaded; a top view of the hypotheses where an estimator kept several;
// a rendered snapshot with every estimator's estimate drawn in. The charts as PNG and SVG, the
// snapshot as PNG, from the first seed; every estimator in its style (estimator_style.h).

#include "drivers/experiment_run.h"
#include "opf/sim/experiment_config.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace opf::experiments {

/// A figure's title: "<experiment>: <object>, <what> (seed N)"; the name said once where the
/// object is called as the experiment ("baseball, translation error (seed 0)").
std::string figure_title(const std::string& experiment, const std::string& object,
                         const std::string& what, std::size_t seed);

/// Writes <experiment>_<object>_{translation_error,rotation_error,trace}.{png,svg}, where an
/// estimator kept more than one hypothesis <experiment>_<object>_<estimator>_hypotheses.{png,svg},
/// and <experiment>_snapshot.png into `dir`; returns the paths written. The trace figure draws
/// the feedback module's alert threshold (results.epsilon_safe). Series on the same values are
/// named together in the legend (coinciding_series.h).
std::vector<std::filesystem::path> write_figures(const std::filesystem::path& dir,
                                                 const sim::ExperimentConfig& config,
                                                 const Observation& observation,
                                                 const ExperimentResults& results);

}  // namespace opf::experiments
