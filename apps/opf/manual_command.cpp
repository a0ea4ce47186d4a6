#include "manual_command.h"

#include "cli/version.h"
#include "command_table.h"

#include <iostream>
#include <sstream>

namespace opf::cli {
namespace {

/// Text as roff reads it literally: backslashes escaped, hyphens as minus signs (so options
/// copy and paste), a control character at a line's start defused, wrapped lines joined.
std::string roff(const std::string& text) {
  std::string out;
  bool line_start = true;
  for (const char c : text) {
    if (line_start && (c == '.' || c == '\'')) out += "\\&";
    line_start = false;
    if (c == '\\')
      out += "\\e";
    else if (c == '-')
      out += "\\-";
    else if (c == '\n')
      out += ' ';
    else
      out += c;
  }
  return out;
}

constexpr const char* kSummary =
    "Prints the man page opf(1) as roff, generated from every command's help. The install puts\n"
    "it in share/man/man1/opf.1; to read it from the build tree: man -l "
    "build/share/man/man1/opf.1.";

}  // namespace

std::string man_page(const std::vector<Command>& commands, const std::string& version) {
  std::ostringstream out;
  out << ".TH OPF 1 \"\" \"opf " << roff(version) << "\" \"User Commands\"\n"
      << ".SH NAME\n"
      << "opf \\- Object Permanence Filter toolkit: 6\\-DoF object tracking through occlusion\n"
      << ".SH SYNOPSIS\n"
      << ".B opf\n.I command\n.RI [ options ]\n.br\n"
      << ".B opf\n.I command\n.B \\-\\-help\n"
      << ".SH DESCRIPTION\n"
      << "Tracks objects from pose detections with the Object Permanence Filter and its "
         "baselines (standard particle filter, constant\\-velocity Kalman filter, "
         "occlusion\\-aware "
         "particle filter), reproduces the paper's experiments and runs parameter sweeps. Every "
         "run is seeded: the same seed gives the same output.\n"
      << ".SH COMMANDS\n";
  for (const Command& command : commands) {
    const CommandHelp help = command.help();
    out << ".SS \"opf " << roff(help.usage) << " [options]\"\n" << roff(help.summary) << "\n";
    for (const OptionSpec& spec : help.options) {
      out << ".TP\n.B \\-\\-" << roff(spec.name);
      if (!spec.value_name.empty()) out << " \\fI" << roff(spec.value_name) << "\\fR";
      out << "\n" << roff(spec.help) << "\n";
    }
  }
  out << ".SH FILES\n"
      << ".TP\n.I <prefix>/libexec/opf/opf-experiments\n"
      << "Runs reproduce, run, render, sweep, detect, completion and manual, which load OpenCV "
         "and OpenGL; opf runs it in its own place for those commands, with the same "
         "arguments.\n"
      << ".TP\n.I <prefix>/share/opf/experiments\n"
      << "The bundled experiment files, estimator settings (configs/estimators.yaml lists every "
         "key with its default) and the example log, found beside the program.\n"
      << ".SH ENVIRONMENT\n"
      << ".TP\n.B OPF_DATA_DIR\n"
      << "Where the bundled data is, instead of <prefix>/share/opf.\n"
      << ".SH EXIT STATUS\n"
      << "0 on success, 1 on an error in the input or a failed run (the message names the file, "
         "line and field), 2 on a bad command line.\n"
      << ".SH SEE ALSO\n"
      << "The manual in the source tree's docs/ (docs/usage.md, docs/formats.md).\n";
  return out.str();
}

CommandHelp manual_help() {
  return {"manual", kSummary, {}};
}

int manual_command(const std::vector<std::string>& raw) {
  const CommandHelp help = manual_help();
  const Arguments args(raw, help.options);
  if (args.help()) {
    std::cout << usage(help);
    return 0;
  }
  std::cout << man_page(commands(), OPF_VERSION);
  return 0;
}

}  // namespace opf::cli
