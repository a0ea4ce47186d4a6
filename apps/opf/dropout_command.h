#pragma once
// `opf dropout`: removes objects' detections from a measurement log in periodic windows.

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

CommandHelp dropout_help();
int dropout_command(const std::vector<std::string>& args);

}  // namespace opf::cli
