// The `opf` command-line program: `opf <command> [options]`, `opf <command> --help`.

#include "arguments.h"
#include "cli/version.h"
#include "config_command.h"
#include "detect_command.h"
#include "dropout_command.h"
#include "evaluate_command.h"
#include "experiment_commands.h"
#include "opf/core/heap_policy.h"
#include "render_command.h"
#include "sweep_command.h"
#include "track_command.h"

#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

constexpr const char* kHelp =
    "Usage: opf <command> [options]\n"
    "\n"
    "Object Permanence Filter toolkit.\n"
    "\n"
    "Commands:\n"
    "  track      replay a measurement log through one estimator and write its estimates\n"
    "  evaluate   compare every estimator against ground truth over several seeds\n"
    "  reproduce  run the paper's simulated experiments and print Table I beside the paper's\n"
    "  run        run one experiment file (rendered scene, every estimator, several seeds)\n"
    "  render     render one frame of an experiment with what the detector sees\n"
    "  sweep      run a grid of experiment runs across the cores, resumable, into one table\n"
    "  detect     segment objects in a real video and write their poses as a measurement log\n"
    "  dropout    remove objects' detections from a measurement log in periodic windows\n"
    "  config     print the effective estimator settings (--dump) as YAML\n"
    "\n"
    "Run 'opf <command> --help' for a command's options.\n";

}  // namespace

int main(int argc, char** argv) {
  opf::retain_freed_heap_memory();  // the filters free and allocate particles every step
  const std::vector<std::string> all(argv + 1, argv + argc);
  if (all.empty() || all[0] == "--help" || all[0] == "-h" || all[0] == "help") {
    std::cout << kHelp;
    return all.empty() ? 2 : 0;
  }
  if (all[0] == "--version" || all[0] == "version") {
    std::cout << "opf " << OPF_VERSION << " (commit " << OPF_COMMIT << ")\n";
    return 0;
  }
  const std::string& command = all[0];
  const std::vector<std::string> rest(all.begin() + 1, all.end());
  try {
    if (command == "track") return opf::cli::track_command(rest);
    if (command == "evaluate") return opf::cli::evaluate_command(rest);
    if (command == "reproduce") return opf::cli::reproduce_command(rest);
    if (command == "run") return opf::cli::run_command(rest);
    if (command == "render") return opf::cli::render_command(rest);
    if (command == "sweep") return opf::cli::sweep_command(rest);
    if (command == "detect") return opf::cli::detect_command(rest);
    if (command == "dropout") return opf::cli::dropout_command(rest);
    if (command == "config") return opf::cli::config_command(rest);
    std::cerr << "opf: unknown command '" << command << "'\n\n" << kHelp;
    return 2;
  } catch (const opf::cli::UsageError& error) {
    std::cerr << "opf " << command << ": " << error.message << " (see 'opf " << command
              << " --help')\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "opf " << command << ": error: " << error.what() << "\n";
    return 1;
  }
}
