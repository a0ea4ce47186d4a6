#pragma once
// `opf render EXPERIMENT.yaml --frame K`: the camera image of one frame with the detections drawn
// in, so a user can see what the detector sees.

#include "command_help.h"

#include <string>
#include <vector>

namespace opf::cli {

CommandHelp render_help();
int render_command(const std::vector<std::string>& args);

}  // namespace opf::cli
