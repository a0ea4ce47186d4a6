#pragma once
// `opf detect`: segments objects in a real video and writes their poses as a measurement log.

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

CommandHelp detect_help();
int detect_command(const std::vector<std::string>& args);

}  // namespace opf::cli
