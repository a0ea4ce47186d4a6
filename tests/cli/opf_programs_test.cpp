// The two programs (apps/opf/command_table.h): `opf` runs the commands that only track without
// loading OpenCV or OpenGL and hands the others to `opf-experiments`; one manner for bad command
// lines in both (exit 2, the near miss suggested).

#include "cli/opf_program.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace opf {
namespace {

namespace fs = std::filesystem;

// The shared libraries `program` loads, as the dynamic loader lists them.
std::string loaded_libraries(const std::string& program) {
  std::string listing;
  FILE* pipe = popen(("ldd " + program).c_str(), "r");
  if (pipe == nullptr) return listing;
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe) != nullptr) listing += buffer;
  pclose(pipe);
  return listing;
}

TEST_F(OpfProgram, TheTrackingProgramLoadsNeitherOpenCvNorOpenGl) {
  const std::string opf = loaded_libraries(kOpf);
  ASSERT_NE(opf.find("libmrpt-poses"), std::string::npos) << opf;  // the listing is real
  for (const char* library : {"libopencv", "libmrpt-opengl", "libmrpt-img", "libEGL", "libGL"})
    EXPECT_EQ(opf.find(library), std::string::npos) << library << " in\n" << opf;
  const fs::path experiments =
      fs::path(kOpf).parent_path().parent_path() / "libexec" / "opf" / "opf-experiments";
  EXPECT_NE(loaded_libraries(experiments.string()).find("libopencv_core"), std::string::npos);
}

TEST_F(OpfProgram, HandsTheRenderingCommandsToTheExperimentsProgram) {
  ASSERT_EQ(run("run --help"), 0) << err();
  EXPECT_NE(out().find("Usage: opf run EXPERIMENT.yaml"), std::string::npos) << out();
  ASSERT_EQ(run("render"), 2);
  EXPECT_NE(err().find("opf render: "), std::string::npos) << err();
  ASSERT_EQ(run("manual"), 0);
  EXPECT_NE(out().find(".SH COMMANDS"), std::string::npos);
}

TEST_F(OpfProgram, WithoutTheExperimentsProgramSaysWhatIsMissing) {
  fs::create_directories(dir_ / "bin");
  const fs::path lone = dir_ / "bin" / "opf";
  fs::copy_file(kOpf, lone);
  const std::string command = lone.string() + " run --help >" + (dir_ / "stdout").string() + " 2>" +
                              (dir_ / "stderr").string();
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(err().find("cannot run " + (dir_ / "libexec" / "opf" / "opf-experiments").string() +
                       ": No such file or directory"),
            std::string::npos)
      << err();
  // The commands that only track still run.
  EXPECT_EQ(std::system((lone.string() + " --version >/dev/null").c_str()), 0);
}

TEST_F(OpfProgram, UnknownNamesGetTheNearMissAndExitTwo) {
  EXPECT_EQ(run("trak --in x"), 2);
  EXPECT_NE(err().find("opf: unknown command 'trak'; did you mean 'track'?"), std::string::npos)
      << err();
  EXPECT_EQ(run("reprodcue"), 2);  // a command of the experiments program
  EXPECT_NE(err().find("did you mean 'reproduce'?"), std::string::npos) << err();
  EXPECT_EQ(run("track --in x --out y --particle 300"), 2);
  EXPECT_NE(err().find("unknown option '--particle'; did you mean '--particles'?"),
            std::string::npos)
      << err();
  EXPECT_EQ(run("track --in x --out y --estimator imn"), 2);
  EXPECT_NE(err().find("option '--estimator': unknown estimator 'imn' (known: opf, pf, cvkf, "
                       "imm, oapf); did you mean 'imm'?"),
            std::string::npos)
      << err();
  EXPECT_EQ(run("evaluate --estimators opf,ekf"), 2);
  EXPECT_NE(err().find("option '--estimators': unknown estimator 'ekf'"), std::string::npos)
      << err();
  EXPECT_EQ(run("run x.yaml --estimators opff"), 2);  // checked before the file is read
  EXPECT_NE(err().find("did you mean 'opf'?"), std::string::npos) << err();
}

}  // namespace
}  // namespace opf
