#include "command_table.h"

#include "opf/core/closest_name.h"

#include <sstream>
#include <stdexcept>

namespace opf::cli {
namespace {

struct CommandLine {
  const char* name;
  const char* line;
};

// The one list of commands and their lines, in the order `opf --help` prints them.
constexpr CommandLine kCommandLines[] = {
    {"track", "replay a measurement log through one estimator and write its estimates"},
    {"evaluate", "compare every estimator against ground truth over several seeds"},
    {"reproduce", "run the paper's simulated experiments and print Table I beside the paper's"},
    {"run", "run one experiment file (rendered scene, every estimator, several seeds)"},
    {"render", "render one frame of an experiment with what the detector sees"},
    {"sweep", "run a grid of experiment runs across the cores, resumable, into one table"},
    {"detect", "segment objects in a real video and write their poses as a measurement log"},
    {"dropout", "remove objects' detections from a measurement log in periodic windows"},
    {"config", "print the effective estimator settings (--dump) as YAML"},
    {"completion", "print the bash completion script (installed with the program)"},
    {"manual", "print the man page opf(1) as roff (installed with the program)"},
};

}  // namespace

std::vector<Command> command_table(const std::vector<CommandImplementation>& implemented) {
  std::vector<Command> table;
  std::size_t matched = 0;
  for (const CommandLine& entry : kCommandLines) {
    Command command{entry.name, entry.line};
    for (const CommandImplementation& implementation : implemented)
      if (implementation.name == entry.name) {
        command.help = implementation.help;
        command.run = implementation.run;
        ++matched;
      }
    table.push_back(command);
  }
  if (matched != implemented.size())
    throw std::logic_error("an implemented command is missing from the command lines");
  return table;
}

std::string program_help() {
  std::ostringstream out;
  out << "Usage: opf <command> [options]\n\nObject Permanence Filter toolkit.\n\nCommands:\n";
  for (const CommandLine& command : kCommandLines) {
    std::string name = std::string("  ") + command.name;
    name.resize(13, ' ');
    out << name << command.line << "\n";
  }
  out << "\nRun 'opf <command> --help' for a command's options.\n";
  return out.str();
}

std::string unknown_command_message(const std::string& command) {
  std::vector<std::string> names;
  for (const CommandLine& entry : kCommandLines) names.emplace_back(entry.name);
  std::string message = "unknown command '" + command + "'";
  if (const auto closest = closest_name(command, names))
    message += "; did you mean '" + *closest + "'?";
  return message;
}

}  // namespace opf::cli
