#include "command_table.h"

#include "completion_command.h"
#include "config_command.h"
#include "detect_command.h"
#include "dropout_command.h"
#include "evaluate_command.h"
#include "experiment_commands.h"
#include "manual_command.h"
#include "render_command.h"
#include "sweep_command.h"
#include "track_command.h"

#include <sstream>

namespace opf::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"track", "replay a measurement log through one estimator and write its estimates",
       track_help, track_command},
      {"evaluate", "compare every estimator against ground truth over several seeds", evaluate_help,
       evaluate_command},
      {"reproduce", "run the paper's simulated experiments and print Table I beside the paper's",
       reproduce_help, reproduce_command},
      {"run", "run one experiment file (rendered scene, every estimator, several seeds)", run_help,
       run_command},
      {"render", "render one frame of an experiment with what the detector sees", render_help,
       render_command},
      {"sweep", "run a grid of experiment runs across the cores, resumable, into one table",
       sweep_help, sweep_command},
      {"detect", "segment objects in a real video and write their poses as a measurement log",
       detect_help, detect_command},
      {"dropout", "remove objects' detections from a measurement log in periodic windows",
       dropout_help, dropout_command},
      {"config", "print the effective estimator settings (--dump) as YAML", config_help,
       config_command},
      {"completion", "print the bash completion script (installed with the program)",
       completion_help, completion_command},
      {"manual", "print the man page opf(1) as roff (installed with the program)", manual_help,
       manual_command},
  };
  return table;
}

std::string program_help() {
  std::ostringstream out;
  out << "Usage: opf <command> [options]\n\nObject Permanence Filter toolkit.\n\nCommands:\n";
  for (const Command& command : commands()) {
    std::string name = "  " + command.name;
    name.resize(13, ' ');
    out << name << command.line << "\n";
  }
  out << "\nRun 'opf <command> --help' for a command's options.\n";
  return out.str();
}

}  // namespace opf::cli
