#include "drivers/sweep_executor.h"

#include "opf/io/atomic_file.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>

extern char** environ;

namespace opf::experiments {
namespace {

std::string clock_text(double seconds) {
  const auto total = static_cast<long>(seconds + 0.5);
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%ld:%02ld", total / 60, total % 60);
  return buffer;
}

class ProgressDisplay {
 public:
  ProgressDisplay(std::ostream& out, bool interactive, std::size_t total, std::size_t skipped)
      : out_(out), interactive_(interactive), total_(total), skipped_(skipped) {}

  void finished(const SweepRun& run, bool ok, std::size_t completed, std::size_t failed) {
    const std::size_t finished_now = completed + failed;
    const double elapsed = seconds_since(start_);
    const std::size_t remaining = total_ - skipped_ - finished_now;
    const std::string eta = finished_now == 0
                                ? "?"
                                : clock_text(elapsed / static_cast<double>(finished_now) *
                                             static_cast<double>(remaining));
    const std::size_t done = skipped_ + finished_now;
    std::string counts = std::to_string(done) + "/" + std::to_string(total_) + " runs (" +
                         std::to_string(skipped_) + " skipped, " + std::to_string(failed) +
                         " failed), " + clock_text(elapsed) + " elapsed, ~" + eta + " left";
    if (interactive_) {
      constexpr std::size_t kWidth = 30;
      const std::size_t filled = total_ == 0 ? kWidth : kWidth * done / total_;
      out_ << "\r\033[K[" << std::string(filled, '#') << std::string(kWidth - filled, '.') << "] "
           << counts << std::flush;
      if (!ok) out_ << "\n  failed: " << run.directory.string() << "\n";
    } else {
      out_ << (ok ? "done   " : "FAILED ") << run.directory.string() << "  " << counts << "\n";
    }
  }
  void close() {
    if (interactive_) out_ << "\n";
  }

 private:
  static double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  std::ostream& out_;
  bool interactive_;
  std::size_t total_;
  std::size_t skipped_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Starts `program args...` with stdout and stderr to `log`; returns its pid.
pid_t spawn(const std::filesystem::path& program, const std::vector<std::string>& args,
            const std::filesystem::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<std::string> storage{program.string()};
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0)
    throw std::runtime_error("cannot start " + program.string() + ": " + std::strerror(error));
  return pid;
}

}  // namespace

SweepExecution execute_sweep(const std::vector<SweepRun>& runs, const std::filesystem::path& out,
                             const std::filesystem::path& program, std::size_t jobs,
                             std::ostream& progress, bool interactive) {
  if (jobs == 0) throw std::invalid_argument("execute_sweep: jobs must be at least 1");
  SweepExecution execution;
  std::vector<const SweepRun*> pending;
  for (const SweepRun& run : runs) {
    if (std::filesystem::exists(out / run.result_file()))
      ++execution.skipped;
    else
      pending.push_back(&run);
  }
  ProgressDisplay display(progress, interactive, runs.size(), execution.skipped);
  std::map<pid_t, const SweepRun*> running;
  std::size_t next = 0;
  const auto wait_one = [&] {
    int status = 0;
    pid_t pid = -1;
    do pid = waitpid(-1, &status, 0);
    while (pid < 0 && errno == EINTR);
    const auto it = running.find(pid);
    if (it == running.end()) return;  // not one of ours
    const SweepRun& run = *it->second;
    running.erase(it);
    const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 &&
                    std::filesystem::exists(out / run.result_file());
    if (ok)
      ++execution.completed;
    else
      execution.failed.push_back(run.directory);
    display.finished(run, ok, execution.completed, execution.failed.size());
  };
  while (next < pending.size() || !running.empty()) {
    if (next < pending.size() && running.size() < jobs) {
      const SweepRun& run = *pending[next++];
      const std::filesystem::path dir = out / run.directory;
      std::filesystem::create_directories(dir);
      write_file_atomically(dir / "settings.yaml",
                            [&](std::ostream& file) { file << run.settings_yaml; });
      try {
        running.emplace(spawn(program, run.arguments(out), dir / "log.txt"), &run);
      } catch (...) {
        while (!running.empty()) wait_one();  // no process is left behind
        throw;
      }
      continue;
    }
    wait_one();
  }
  display.close();
  return execution;
}

}  // namespace opf::experiments
