// `opf track` loses no data: it never writes over its input (nor does any other command),
// writes through FIFOs and devices, checks every write, leaves no temporary file when
// interrupted, and takes a bounded number of threads.

#include "cli/opf_program.h"

#include <sys/stat.h>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace opf {
namespace {

namespace fs = std::filesystem;

const std::string kLog = std::string(OPF_SOURCE_DIR) + "/experiments/data/example_log.csv";

// Runs a shell command line (for redirections the fixture's run() does not make) and returns its
// exit status.
int shell(const std::string& line) {
  const int status = std::system(("bash -c '" + line + "'").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_F(OpfProgram, TrackRefusesToWriteOverItsInput) {
  const fs::path log = dir_ / "log.csv", link = dir_ / "link.csv";
  fs::copy_file(kLog, log);
  fs::create_symlink(log, link);
  const std::string before = read(log);
  for (const fs::path& out : {log, link})
    for (const char* mode : {"", " --stream"}) {
      EXPECT_EQ(run("track --in " + log.string() + " --out " + out.string() + mode), 2) << mode;
      EXPECT_NE(err().find("--out '" + out.string() + "' is the same file as --in '" +
                           log.string() + "': one would overwrite the other"),
                std::string::npos)
          << err();
    }
  EXPECT_EQ(read(log), before);
}

// No command writes over a file it reads, nor two outputs over each other: `opf dropout` and
// `opf evaluate --out` replaced the log, `--hidden-profile` the truth, without a word. Nor does
// one take a file for the folder its results go to.
TEST_F(OpfProgram, NoCommandWritesOverItsInputs) {
  const fs::path log = dir_ / "log.csv", truth = dir_ / "truth.csv", settings = dir_ / "s.yaml",
                 spec = dir_ / "spec.yaml", experiment = dir_ / "experiment.yaml";
  fs::copy_file(kLog, log);
  fs::copy_file(std::string(OPF_SOURCE_DIR) + "/experiments/data/example_truth.csv", truth);
  fs::copy_file(std::string(OPF_SOURCE_DIR) + "/experiments/configs/paper.yaml", settings);
  fs::copy_file(std::string(OPF_SOURCE_DIR) + "/experiments/real_video/box.yaml", spec);
  fs::copy_file(std::string(OPF_SOURCE_DIR) + "/experiments/general_op.yaml", experiment);
  std::map<fs::path, std::string> before;
  for (const fs::path& file : {log, truth, settings, spec, experiment}) before[file] = read(file);
  const std::string evaluate =
      "evaluate --seeds 1 --estimators cvkf --in " + log.string() + " --truth " + truth.string();
  const fs::path profile = dir_ / "profile.csv";
  std::map<std::string, std::string> refused = {
      {"dropout --length 0.5 --in " + log.string() + " --out " + log.string(),
       "--out '" + log.string() + "' is the same file as --in"},
      {evaluate + " --out " + log.string(),
       "--out '" + log.string() + "' is the same file as --in"},
      {evaluate + " --hidden-profile " + truth.string(),
       "--hidden-profile '" + truth.string() + "' is the same file as --truth"},
      {evaluate + " --out " + (dir_ / "." / "truth.csv").string(), "is the same file as --truth"},
      {evaluate + " --out " + profile.string() + " --hidden-profile " + profile.string(),
       "--hidden-profile '" + profile.string() + "' is the same file as --out"},
      {"track --in " + log.string() + " --config " + settings.string() + " --out " +
           settings.string(),
       "--out '" + settings.string() + "' is the same file as --config"},
      {"detect --video " + (dir_ / "none.mp4").string() + " --objects " + spec.string() +
           " --out " + spec.string(),
       "--out '" + spec.string() + "' is the same file as --objects"},
      {"detect --video " + dir_.string() + " --objects " + spec.string() + " --out " +
           (dir_ / "new.csv").string() + " --overlay " + (dir_ / ".").string(),
       "--overlay '" + (dir_ / ".").string() + "' is the same file as --video"},
      {"render " + experiment.string() + " --out " + experiment.string(),
       "--out '" + experiment.string() + "' is the same file as the experiment file"}};
  // A folder for the results that is a file: refused in the program's words (it was the
  // library's "filesystem error: cannot create directories").
  for (const std::string& command :
       {"run " + experiment.string() + " --seeds 1 --estimators cvkf --out " + log.string(),
        "sweep " + std::string(OPF_SOURCE_DIR) + "/experiments/sweeps/smoke.yaml --list --out " +
            log.string(),
        "detect --video " + (dir_ / "none.mp4").string() + " --objects " + spec.string() +
            " --out " + (dir_ / "new.csv").string() + " --overlay " + log.string()})
    refused[command] = "'" + log.string() + "' is a file: it names the folder the results go to";
  for (const auto& [command, message] : refused) {
    EXPECT_EQ(run(command), 2) << command;
    EXPECT_NE(err().find(message), std::string::npos) << command << "\n" << err();
  }
  for (const auto& [file, text] : before) EXPECT_EQ(read(file), text) << file;
  EXPECT_FALSE(fs::exists(profile));
}

TEST_F(OpfProgram, TrackReportsAFullDeviceAndExitsNonZero) {
  for (const char* mode : {"", " --stream"}) {
    EXPECT_EQ(run("track --quiet --in " + kLog + " --out /dev/full" + mode), 1) << mode;
    EXPECT_NE(err().find("cannot write the estimates to '/dev/full': No space left on device"),
              std::string::npos)
        << err();
    const std::string errors = (dir_ / "stderr").string();
    EXPECT_EQ(
        shell(kOpf + " track --quiet --in " + kLog + " --out -" + mode + " >/dev/full 2>" + errors),
        1)
        << mode;
    EXPECT_NE(err().find("cannot write the estimates to standard output"), std::string::npos)
        << err();
  }
}

TEST_F(OpfProgram, TrackEndsAtOnceOnAClosedPipe) {
  // With SIGPIPE ignored (as a Python parent leaves it), the failed write is the signal: the run
  // ends with an error instead of tracking the whole log into nowhere.
  const std::string errors = (dir_ / "stderr").string();
  EXPECT_EQ(shell("trap \"\" PIPE; " + kOpf + " track --quiet --stream --in " + kLog +
                  " --out - 2>" + errors + " | head -c 100 >/dev/null; exit ${PIPESTATUS[0]}"),
            1);
  EXPECT_NE(err().find("Broken pipe"), std::string::npos) << err();
}

TEST_F(OpfProgram, TrackWritesThroughAFifo) {
  const fs::path fifo = dir_ / "fifo", got = dir_ / "got.csv", file = dir_ / "file.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // The reader runs in the background and ends when the writer closes the FIFO.
  EXPECT_EQ(shell("cat " + fifo.string() + " >" + got.string() + " & " + kOpf +
                  " track --quiet --in " + kLog + " --out " + fifo.string() + "; wait"),
            0);
  EXPECT_TRUE(fs::is_fifo(fifo));
  ASSERT_EQ(run("track --quiet --in " + kLog + " --out " + file.string()), 0) << err();
  EXPECT_EQ(read(got), read(file));
}

TEST_F(OpfProgram, TrackLeavesNoTemporaryFileWhenInterrupted) {
  // 3000 frames at 100 000 particles: seconds of tracking, into the temporary file.
  const fs::path log = dir_ / "long.csv", out = dir_ / "est.csv";
  {
    std::ofstream file(log);
    file << "t,object,x,y,z,qx,qy,qz,qw\n";
    for (int k = 0; k < 3000; ++k)
      file << k / 30.0 << ",box," << 0.5 + 0.001 * k << ",0,0,0,0,0,1\n";
  }
  for (const char* signal : {"INT", "TERM"}) {
    // Sent once the temporary exists; the run ends as the signal ends it (128 + its number).
    const std::string line = kOpf + " track --quiet --particles 100000 --in " + log.string() +
                             " --out " + out.string() + " & pid=$!; for i in $(seq 200); do " +
                             "ls " + out.string() +
                             ".tmp.* >/dev/null 2>&1 && break; sleep 0.05; " + "done; kill -" +
                             signal + " $pid; wait $pid";
    EXPECT_EQ(shell(line), std::string(signal) == "INT" ? 130 : 143) << signal;
    for (const auto& entry : fs::directory_iterator(dir_))
      EXPECT_EQ(entry.path().filename().string().rfind("est.csv", 0), std::string::npos)
          << entry.path() << " after SIG" << signal;
  }
}

TEST_F(OpfProgram, ThreadsAreBounded) {
  EXPECT_EQ(run("track --in " + kLog + " --out " + (dir_ / "a.csv").string() + " --threads 257"),
            2);
  EXPECT_NE(err().find("'--threads' must be at most 256, got 257"), std::string::npos) << err();
  EXPECT_EQ(
      run("track --quiet --in " + kLog + " --out " + (dir_ / "b.csv").string() + " --threads 256"),
      0)
      << err();
}

}  // namespace
}  // namespace opf
