#pragma once
// `opf render EXPERIMENT.yaml --frame K`: the camera image of one frame with the detections drawn
// in, so a user can see what the detector sees.

#include <string>
#include <vector>

namespace opf::cli {

int render_command(const std::vector<std::string>& args);

}  // namespace opf::cli
