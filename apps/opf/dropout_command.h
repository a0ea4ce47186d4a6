#pragma once
// `opf dropout`: removes objects' detections from a measurement log in periodic windows.

#include <string>
#include <vector>

namespace opf::cli {

int dropout_command(const std::vector<std::string>& args);

}  // namespace opf::cli
