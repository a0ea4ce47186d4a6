#pragma once
// `opf evaluate`: replays a measurement log through every estimator over several seeds and prints
// the error table against a ground-truth file (the main job until `opf reproduce` lands).

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

CommandHelp evaluate_help();
int evaluate_command(const std::vector<std::string>& args);

}  // namespace opf::cli
