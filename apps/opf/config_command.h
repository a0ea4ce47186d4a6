#pragma once
// `opf config --dump`: the effective estimator settings (defaults, preset, settings file,
// options) as YAML in the settings file's shape.

#include <string>
#include <vector>

namespace opf::cli {

int config_command(const std::vector<std::string>& args);

}  // namespace opf::cli
