#pragma once
// A directory of the running test's own under the system's temporary directory: ctest runs tests
// in parallel, each in its own process, so a name shared by a file's tests would let two tests
// write one file at once. Named after the test, it is reused by the next run, not left per run.
// scratch_directory keeps what the test wrote into it so far (a helper may write several files);
// empty_scratch_directory starts it afresh (a fixture's SetUp).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace opf {

inline std::filesystem::path scratch_directory(const std::string& name) {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    (name + "_" + test->test_suite_name() + "_" + test->name());
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::filesystem::path empty_scratch_directory(const std::string& name) {
  std::filesystem::path dir = scratch_directory(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace opf
