#include "opf/io/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace opf {
namespace {

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("opf_atomic_file_test_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::size_t files_in_dir() const {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir_),
                                                  std::filesystem::directory_iterator()));
  }
  static std::string read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  std::filesystem::path dir_;
};

TEST_F(AtomicFile, WritesTheContent) {
  const auto path = dir_ / "out.csv";
  write_file_atomically(path, [](std::ostream& out) { out << "a,b\n1,2\n"; });
  EXPECT_EQ(read(path), "a,b\n1,2\n");
  EXPECT_EQ(files_in_dir(), 1u);  // no temporary left behind
}

TEST_F(AtomicFile, ReplacesAnExistingFile) {
  const auto path = dir_ / "out.csv";
  std::ofstream(path) << "old content that is longer";
  write_file_atomically(path, [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(read(path), "new");
  EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(AtomicFile, ThroughALinkReplacesTheFileItNames) {
  const auto file = dir_ / "results.csv", link = dir_ / "latest.csv";
  std::ofstream(file) << "old";
  std::filesystem::create_symlink(file, link);
  write_file_atomically(link, [](std::ostream& out) { out << "new"; });
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(read(file), "new");
  EXPECT_EQ(files_in_dir(), 2u);
}

TEST_F(AtomicFile, FailedWriteLeavesNoFileAndNoTemporary) {
  const auto path = dir_ / "out.csv";
  EXPECT_THROW(write_file_atomically(path,
                                     [](std::ostream& out) {
                                       out << "partial,row\n";
                                       throw std::domain_error("estimator diverged");
                                     }),
               std::domain_error);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(AtomicFile, FailedWriteKeepsThePreviousFile) {
  const auto path = dir_ / "out.csv";
  std::ofstream(path) << "complete";
  EXPECT_THROW(write_file_atomically(path,
                                     [](std::ostream& out) {
                                       out << "partial";
                                       throw std::runtime_error("interrupted");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read(path), "complete");
  EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(AtomicFile, StreamFailureIsAnError) {
  const auto path = dir_ / "out.csv";
  EXPECT_THROW(
      write_file_atomically(path, [](std::ostream& out) { out.setstate(std::ios::badbit); }),
      std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(AtomicFile, UnwritableLocationNamesThePath) {
  const auto path = dir_ / "no_such_dir" / "out.csv";
  try {
    write_file_atomically(path, [](std::ostream& out) { out << "x"; });
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace opf
