#pragma once
// `opf run EXPERIMENT.yaml` (one experiment) and `opf reproduce` (the paper's experiments): render
// the scene, run every estimator over seeds on the same measurement stream, print the results
// table, and write per-frame CSVs and summary.json.

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

CommandHelp run_help();
CommandHelp reproduce_help();
int run_command(const std::vector<std::string>& args);
int reproduce_command(const std::vector<std::string>& args);

}  // namespace opf::cli
