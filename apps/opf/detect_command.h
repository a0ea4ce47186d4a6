#pragma once
// `opf detect`: segments objects in a real video and writes their poses as a measurement log.

#include <string>
#include <vector>

namespace opf::cli {

int detect_command(const std::vector<std::string>& args);

}  // namespace opf::cli
