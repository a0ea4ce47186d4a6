#pragma once
// Every `opf` command in one table: its name, its line in `opf --help`, its help and what runs
// it. main() dispatches through it; the bash completion and the man page are generated from it.
//
// The commands come in two programs, so that tracking starts fast: `opf` runs the commands that
// only track (opf::opf: no OpenCV, no OpenGL) and hands the others, which render scenes or read
// video, to `opf-experiments` (experiments_program.h), which runs every command.

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

/// A command this program runs itself.
struct CommandImplementation {
  std::string name;
  CommandHelp (*help)();
  int (*run)(const std::vector<std::string>& args);
};

struct Command {
  std::string name;
  std::string line;                 ///< the one-line description in `opf --help`
  CommandHelp (*help)() = nullptr;  ///< nullptr: run by the experiments program
  int (*run)(const std::vector<std::string>& args) = nullptr;
};

/// Every command, in `opf --help` order, with the implementations given; a command without one
/// is left to the experiments program. Throws std::logic_error for an implementation of no
/// command.
std::vector<Command> command_table(const std::vector<CommandImplementation>& implemented);

/// This program's table: tracking_commands.cpp in `opf`, every_command.cpp in `opf-experiments`.
const std::vector<Command>& commands();

/// `opf --help`: the usage line and one line per command.
std::string program_help();

/// "unknown command 'X'", with "; did you mean 'Y'?" for a near miss.
std::string unknown_command_message(const std::string& command);

}  // namespace opf::cli
