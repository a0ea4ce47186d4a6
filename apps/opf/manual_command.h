#pragma once
// `opf manual`: the man page opf(1) in roff, generated from the commands' help.

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

struct Command;

/// The page: name, synopsis, description, one section per command with its summary and
/// options, files and environment.
std::string man_page(const std::vector<Command>& commands, const std::string& version);

CommandHelp manual_help();
int manual_command(const std::vector<std::string>& args);

}  // namespace opf::cli
