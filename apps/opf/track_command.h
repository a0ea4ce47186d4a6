#pragma once
// `opf track`: replays a measurement log through one estimator and writes its estimates.

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

CommandHelp track_help();
int track_command(const std::vector<std::string>& args);

}  // namespace opf::cli
