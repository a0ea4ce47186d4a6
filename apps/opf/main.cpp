// The `opf` command-line program: `opf <command> [options]`, `opf <command> --help`. The same
// main() is `opf-experiments`'s, with that program's command table (command_table.h).

#include "arguments.h"
#include "cli/version.h"
#include "command_table.h"
#include "experiments_program.h"
#include "opf/core/heap_policy.h"
#include "opf/io/atomic_file.h"

#include <csignal>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

namespace {

// Interrupted (Ctrl-C, or `kill`), the program removes the temporary file of a result it was
// writing, then ends as the signal would have ended it (the handler is reset on entry).
extern "C" void on_interrupt(int signal) {
  opf::remove_open_temporary_files();
  std::raise(signal);
}

void remove_temporaries_when_interrupted() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  for (int signal : {SIGINT, SIGTERM}) sigaction(signal, &action, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  opf::retain_freed_heap_memory();  // the filters free and allocate particles every step
  remove_temporaries_when_interrupted();
  const std::vector<std::string> all(argv + 1, argv + argc);
  if (all.empty() || all[0] == "--help" || all[0] == "-h" || all[0] == "help") {
    std::cout << opf::cli::program_help();
    return all.empty() ? 2 : 0;
  }
  if (all[0] == "--version" || all[0] == "version") {
    std::cout << "opf " << OPF_VERSION << " (commit " << OPF_COMMIT << ")\n";
    return 0;
  }
  const std::string& command = all[0];
  const std::vector<std::string> rest(all.begin() + 1, all.end());
  try {
    for (const opf::cli::Command& entry : opf::cli::commands()) {
      if (entry.name != command) continue;
      if (entry.run == nullptr) opf::cli::run_experiments_program(argv);
      return entry.run(rest);
    }
    std::cerr << "opf: " << opf::cli::unknown_command_message(command) << "\n\n"
              << opf::cli::program_help();
    return 2;
  } catch (const opf::cli::UsageError& error) {
    std::cerr << "opf " << command << ": " << error.message << " (see 'opf " << command
              << " --help')\n";
    return 2;
  } catch (const std::bad_alloc&) {
    // Most likely the particles asked for: say which setting to lower, not just "bad_alloc".
    std::cerr << "opf " << command
              << ": error: out of memory: the run needs more memory than this machine has; "
                 "fewer particles (--particles, pf.translation_particles and "
                 "pf.rotation_particles) or objects need less\n";
    return 1;
  } catch (const std::exception& error) {
    std::cerr << "opf " << command << ": error: " << error.what() << "\n";
    return 1;
  }
}
