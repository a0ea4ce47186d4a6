#pragma once
// What `opf <command> --help` prints, as data: the one source of a command's help text, its shell
// completion and its section of the man page.

#include "arguments.h"

#include <string>
#include <vector>

namespace opf::cli {

struct CommandHelp {
  std::string usage;  ///< after "opf ": the command and its positional arguments
  std::string summary;
  std::vector<OptionSpec> options;
};

/// "Usage: opf <usage> [options]", the summary and one line per option.
inline std::string usage(const CommandHelp& help) {
  return usage(help.usage, help.summary, help.options);
}

}  // namespace opf::cli
