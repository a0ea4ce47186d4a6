#include "opf/io/input_file.h"

#include "opf/io/input_error.h"

#include <gtest/gtest.h>

#include <unistd.h>

namespace opf {
namespace {

class InputFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        std::filesystem::temp_directory_path() / ("opf_input_file_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string message_of(const std::filesystem::path& path) {
    try {
      open_input_file(path, "measurement log");
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path.string());
      EXPECT_EQ(e.line(), 0u);
      return e.message();
    }
    ADD_FAILURE() << "no error for " << path;
    return "";
  }
  std::filesystem::path dir_;
};

TEST_F(InputFile, MissingFileAndDirectoryAreNamedErrors) {
  EXPECT_EQ(message_of(dir_ / "absent.csv"), "measurement log not found");
  EXPECT_EQ(message_of(dir_), "expected a measurement log file, got a directory");
}

TEST_F(InputFile, OpensAReadableFile) {
  std::ofstream(dir_ / "log.csv") << "t\n";
  std::ifstream in = open_input_file(dir_ / "log.csv", "measurement log");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "t");
}

}  // namespace
}  // namespace opf
