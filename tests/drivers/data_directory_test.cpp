#include "drivers/data_directory.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace {

// Sets an environment variable for one scope and restores it after.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(DataDirectory, IsTheProgramsPrefixShareOpf) {
  ScopedEnv unset("OPF_DATA_DIR", "");
  // The test program runs from build/bin; the build stages the experiments at build/share/opf.
  const auto dir = opf::experiments::data_directory();
  EXPECT_TRUE(std::filesystem::equivalent(dir / "experiments",
                                          std::filesystem::path(OPF_SOURCE_DIR) / "experiments"));
  EXPECT_EQ(dir.filename(), "opf");
  EXPECT_EQ(dir.parent_path().filename(), "share");
}

TEST(DataDirectory, EnvironmentOverridesAndAWrongPlaceIsNamed) {
  ScopedEnv set("OPF_DATA_DIR", OPF_SOURCE_DIR);  // holds experiments/ too
  EXPECT_EQ(opf::experiments::bundled_experiments(),
            std::filesystem::path(OPF_SOURCE_DIR) / "experiments");
  ScopedEnv wrong("OPF_DATA_DIR", "/nonexistent/prefix/share/opf");
  try {
    opf::experiments::data_directory();
    FAIL() << "no error for a folder without experiments/";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot find the bundled experiments in /nonexistent/prefix/share/opf/experiments "
              "(from OPF_DATA_DIR; set OPF_DATA_DIR to the folder that holds experiments/)");
  }
}

}  // namespace
