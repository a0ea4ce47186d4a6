// Start-up: the whole `opf` process, from spawn to exit, for the commands a script runs per log
// (--version, track on a 10-row log, evaluate --help, config --dump), against a program that
// links opf::opf alone (examples/track_frames: 45 frames of the OPF). The program's commands that
// only track load no OpenCV and no OpenGL (apps/opf/command_table.h), so they should start about
// as fast as that program. Wall-clock time, one process per iteration.

#include "drivers/data_directory.h"

#include <benchmark/benchmark.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace opf {
namespace {

// Runs `argv` with standard output and error sent to /dev/null and waits for it; throws when it
// cannot be started or does not exit 0.
void run_to_completion(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) throw std::runtime_error(argv[0] + ": " + std::strerror(error));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(argv[0] + " " + argv[1] + " did not exit 0");
}

// The first 10 rows of the bundled example log, in the temporary folder.
std::string ten_row_log() {
  const auto path = std::filesystem::temp_directory_path() /
                    ("opf_startup_log_" + std::to_string(getpid()) + ".csv");
  std::ifstream in(experiments::bundled_experiments() / "data" / "example_log.csv");
  std::ofstream out(path);
  std::string line;
  for (int row = 0; row <= 10 && std::getline(in, line); ++row) out << line << '\n';
  return path.string();
}

void time_process(benchmark::State& state, const std::vector<std::string>& argv) {
  for (auto _ : state) {
    try {
      run_to_completion(argv);
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      break;
    }
  }
}

void BM_StartUp(benchmark::State& state, const std::string& command) {
  const std::string opf = OPF_PROGRAM;
  if (command == "version") time_process(state, {opf, "--version"});
  if (command == "evaluate") time_process(state, {opf, "evaluate", "--help"});
  if (command == "config") time_process(state, {opf, "config", "--dump"});
  if (command == "track") {
    const std::string log = ten_row_log();
    const std::string out = log + ".estimates.csv";
    time_process(state, {opf, "track", "--in", log, "--out", out, "--quiet"});
    std::filesystem::remove(log);
    std::filesystem::remove(out);
  }
}

void BM_StartUpLinkingOpfAlone(benchmark::State& state) {
  time_process(state, {OPF_TRACK_FRAMES_EXAMPLE});
}

BENCHMARK_CAPTURE(BM_StartUp, version, std::string("version"))
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StartUp, track, std::string("track"))
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StartUp, evaluate, std::string("evaluate"))
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StartUp, config, std::string("config"))
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StartUpLinkingOpfAlone)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace opf
