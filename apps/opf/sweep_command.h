#pragma once
// `opf sweep SWEEP.yaml`: a grid of experiment runs (experiments/sweeps/), executed across the
// machine's cores with resume, aggregated into one tidy CSV.

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

CommandHelp sweep_help();
int sweep_command(const std::vector<std::string>& args);

}  // namespace opf::cli
