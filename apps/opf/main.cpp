// The `opf` command-line program: `opf <command> [options]`, `opf <command> --help`.

#include "arguments.h"
#include "cli/version.h"
#include "command_table.h"
#include "opf/core/heap_policy.h"

#include <exception>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  opf::retain_freed_heap_memory();  // the filters free and allocate particles every step
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
    for (const opf::cli::Command& entry : opf::cli::commands())
      if (entry.name == command) return entry.run(rest);
    std::cerr << "opf: unknown command '" << command << "'\n\n" << opf::cli::program_help();
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
