#pragma once
// The fixture of the end-to-end tests of the `opf` program: a fresh directory per test and a way
// to run the built binary with its output captured.

#include "io/scratch_directory.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace opf {

inline const std::string kOpf = OPF_CLI_PATH;
class OpfProgram : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = empty_scratch_directory("opf_cli"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// Runs `opf ARGS`, stdout and stderr to files; returns the exit status.
  int run(const std::string& args) {
    const std::string command =
        kOpf + " " + args + " >" + (dir_ / "stdout").string() + " 2>" + (dir_ / "stderr").string();
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string read(const std::filesystem::path& path) const {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string out() const { return read(dir_ / "stdout"); }
  std::string err() const { return read(dir_ / "stderr"); }

  /// A copy of the CSV log `from` in the test's directory with a `radius` column stated on
  /// every row; returns its path.
  std::filesystem::path with_radius(const std::string& from, const std::string& radius) const {
    std::ifstream in(from);
    const std::filesystem::path path = dir_ / "sized.csv";
    std::ofstream sized(path);
    std::string line;
    for (bool header = true; std::getline(in, line); header = false)
      sized << line << (header ? ",radius" : "," + radius) << "\n";
    return path;
  }

  std::filesystem::path dir_;
};

}  // namespace opf
