#pragma once
// `opf completion`: the bash completion script, generated from the commands' option tables.

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

struct Command;

/// The script: commands, each command's options, and values where they are known (files,
/// directories, estimator names, presets).
std::string bash_completion(const std::vector<Command>& commands);

CommandHelp completion_help();
int completion_command(const std::vector<std::string>& args);

}  // namespace opf::cli
