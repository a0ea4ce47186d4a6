#include "drivers/data_directory.h"

#include <cstdlib>
#include <stdexcept>
#include <system_error>

namespace opf::experiments {

std::filesystem::path data_directory() {
  std::filesystem::path dir;
  std::string origin;
  if (const char* env = std::getenv("OPF_DATA_DIR"); env != nullptr && *env != '\0') {
    dir = env;
    origin = "OPF_DATA_DIR";
  } else {
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error)
      throw std::runtime_error("cannot locate the bundled experiments: /proc/self/exe: " +
                               error.message() + " (set OPF_DATA_DIR to <prefix>/share/opf)");
    // <prefix>/bin/opf, or <prefix>/libexec/opf/opf-experiments.
    const std::filesystem::path prefix = program.parent_path().parent_path();
    dir = prefix / "share" / "opf";
    if (!std::filesystem::is_directory(dir / "experiments") &&
        std::filesystem::is_directory(prefix.parent_path() / "share" / "opf" / "experiments"))
      dir = prefix.parent_path() / "share" / "opf";
    origin = "the program's prefix";
  }
  if (!std::filesystem::is_directory(dir / "experiments"))
    throw std::runtime_error("cannot find the bundled experiments in " +
                             (dir / "experiments").string() + " (from " + origin +
                             "; set OPF_DATA_DIR to the folder that holds experiments/)");
  return dir;
}

std::filesystem::path bundled_experiments() {
  return data_directory() / "experiments";
}

}  // namespace opf::experiments
