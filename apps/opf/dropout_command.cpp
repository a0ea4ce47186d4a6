#include "dropout_command.h"

#include "arguments.h"
#include "command_help.h"
#include "opf/io/atomic_file.h"
#include "opf/io/input_file.h"
#include "opf/io/measurement_dropout.h"
#include "opf/io/measurement_log.h"
#include "output_paths.h"

#include <fstream>
#include <iostream>

namespace opf::cli {
namespace {

std::vector<OptionSpec> specs() {
  return {
      {"in", "LOG.csv",
       "measurement log: CSV with columns t,object,x,y,z,qx,qy,qz,qw, or t,object,x,y,z "
       "(required)"},
      {"out", "LOG.csv", "the log with the detections in the windows removed (required)"},
      {"length", "S", "length of each window in seconds, shorter than the period (required)"},
      {"period", "S", "seconds from one window's start to the next (default 2)"},
      {"start", "S", "start of the first window, in the log's time t (default 1)"},
      {"objects", "A,B,...", "objects whose detections to remove (default: every object)"},
  };
}

constexpr const char* kSummary =
    "Copies a measurement log and removes the detections of the chosen objects whose t lies in\n"
    "a window [start + k period, start + k period + length), k = 0, 1, 2, ... (times within\n"
    "1e-9 s of an edge count as on it). A removed detection keeps its row with its pose fields\n"
    "empty, so that its frame stays in the log: the object is unobserved there. Every\n"
    "other row, and the row order, are copied unchanged, so the input log is the ground truth\n"
    "of the removed frames (opf evaluate --in OUT --truth IN). Deterministic.";

}  // namespace

CommandHelp dropout_help() {
  return {"dropout", kSummary, specs()};
}

int dropout_command(const std::vector<std::string>& raw) {
  const auto option_specs = specs();
  const Arguments args(raw, option_specs);
  if (args.help()) {
    std::cout << usage(dropout_help());
    return 0;
  }
  const std::string in = args.require("in");
  const std::string out = args.require("out");
  // The input is the truth of the removed frames: it must survive.
  refuse_output_over_input({"--out", out}, {{"--in", in}});
  DropoutWindows windows;
  args.require("length");
  windows.length = *args.get_number("length");
  windows.period = args.get_number("period").value_or(windows.period);
  windows.start = args.get_number("start").value_or(windows.start);
  if (!(windows.period > 0.0)) throw UsageError{"option '--period' expects seconds > 0"};
  if (!(windows.length > 0.0 && windows.length < windows.period))
    throw UsageError{"option '--length' expects seconds > 0 and shorter than --period"};
  const std::vector<std::string> objects =
      args.has("objects") ? split_list(*args.get("objects")) : std::vector<std::string>{};
  if (args.has("objects") && objects.empty())
    throw UsageError{"option '--objects' expects a list of object names"};

  read_measurement_log(in);  // the whole log is checked before anything is written
  DropoutCounts counts;
  write_file_atomically(out, [&](std::ostream& os) {
    std::ifstream input = open_input_file(in, "measurement log");
    counts = apply_dropout(input, in, os, objects, windows);
  });
  std::cout << "opf dropout: removed " << counts.blanked << " of " << counts.rows
            << " rows (windows of " << windows.length << " s every " << windows.period
            << " s from t = " << windows.start << " s) into " << out << "\n";
  return 0;
}

}  // namespace opf::cli
