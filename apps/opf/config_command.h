#pragma once
// `opf config --dump`: the effective estimator settings (defaults, preset, settings file,
// options) as YAML in the settings file's shape.

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

CommandHelp config_help();
int config_command(const std::vector<std::string>& args);

}  // namespace opf::cli
