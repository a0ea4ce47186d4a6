#pragma once
// `opf run EXPERIMENT.yaml` (one experiment) and `opf reproduce` (the paper's experiments): render
// the scene, run every estimator over seeds on the same measurement stream, print the results
// table, and write per-frame CSVs and summary.json.

#include "command_help.h"
#include "opf/estimators/estimator_settings.h"

#include <string>
#include <vector>

namespace opf::sim {
struct ExperimentConfig;
}

namespace opf::cli {

CommandHelp run_help();
CommandHelp reproduce_help();
int run_command(const std::vector<std::string>& args);
int reproduce_command(const std::vector<std::string>& args);

/// `settings` as an experiment runs them: the occluder module's line of sight starts at the
/// experiment's camera unless the settings place one themselves.
EstimatorSettings with_experiment_camera(EstimatorSettings settings,
                                         const sim::ExperimentConfig& config);

}  // namespace opf::cli
