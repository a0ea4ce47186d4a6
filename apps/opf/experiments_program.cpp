#include "experiments_program.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace opf::cli {

void run_experiments_program(char** argv) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
    throw std::runtime_error("cannot locate the experiments program: /proc/self/exe: " +
                             error.message());
  // The same relative place in the build tree and in an installed prefix (CMake sets it).
  const std::filesystem::path program =
      (self.parent_path() / OPF_EXPERIMENTS_PROGRAM).lexically_normal();
  execv(program.c_str(), argv);
  throw std::runtime_error("cannot run " + program.string() + ": " + std::strerror(errno) +
                           " (it runs the commands that render scenes or read video, and is "
                           "installed with opf)");
}

}  // namespace opf::cli
