#pragma once
// Every `opf` command in one table: its name, its line in `opf --help`, its help and what runs
// it. main() dispatches through it; the bash completion and the man page are generated from it.

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

struct Command {
  std::string name;
  std::string line;  ///< the one-line description in `opf --help`
  CommandHelp (*help)();
  int (*run)(const std::vector<std::string>& args);
};

const std::vector<Command>& commands();

/// `opf --help`: the usage line and one line per command.
std::string program_help();

}  // namespace opf::cli
