#pragma once
// Where the bundled experiment files live: <prefix>/share/opf/experiments beside an installed
// program, and the same relative place in the build tree (build/share/opf, staged by CMake), so
// that nothing compiled into the program points at the source tree.

#include <filesystem>

namespace opf::experiments {

/// $OPF_DATA_DIR when set, else <prefix>/share/opf for a program in <prefix>/bin or
/// <prefix>/libexec/opf. Throws
/// std::runtime_error naming the place looked at when it holds no experiments/ folder.
std::filesystem::path data_directory();

/// data_directory() / "experiments".
std::filesystem::path bundled_experiments();

}  // namespace opf::experiments
