// `opf-experiments`'s table: every command, those that render scenes or read video included.
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

namespace opf::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = command_table({
      {"track", track_help, track_command},
      {"evaluate", evaluate_help, evaluate_command},
      {"reproduce", reproduce_help, reproduce_command},
      {"run", run_help, run_command},
      {"render", render_help, render_command},
      {"sweep", sweep_help, sweep_command},
      {"detect", detect_help, detect_command},
      {"dropout", dropout_help, dropout_command},
      {"config", config_help, config_command},
      {"completion", completion_help, completion_command},
      {"manual", manual_help, manual_command},
  });
  return table;
}

}  // namespace opf::cli
