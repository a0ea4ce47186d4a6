// `opf`'s table: the commands that only track run here; the others are handed to the
// experiments program.
#include "command_table.h"
#include "config_command.h"
#include "dropout_command.h"
#include "evaluate_command.h"
#include "track_command.h"

namespace opf::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = command_table({
      {"track", track_help, track_command},
      {"evaluate", evaluate_help, evaluate_command},
      {"dropout", dropout_help, dropout_command},
      {"config", config_help, config_command},
  });
  return table;
}

}  // namespace opf::cli
