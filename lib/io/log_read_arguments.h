#pragma once
// The log options as a caller receives them (the program's --time-unit, the Python module's
// time_unit), checked and mapped onto LogReadOptions in one place: the program and the module
// read a log alike and word their refusals alike, each naming options its own way.

#include "opf/io/log_read_options.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace opf {

struct LogArguments {
  std::optional<std::string> format;       ///< csv, tum or mot; unset: detected from the file
  std::optional<std::string> object;       ///< the one object of a log without an object column
  std::optional<std::string> time_unit;    ///< s, ms, us or ns; unset: s, checked
  std::optional<std::string> length_unit;  ///< m or mm; unset: m, checked
  std::optional<std::string> columns;      ///< NAME=COL,...
  std::optional<double> frame_tolerance;   ///< s >= 0; unset: inferred
  std::optional<double> rate;              ///< Hz > 0; unset: inferred (kMot: seqinfo.ini)
  bool fill = true;                        ///< false: only the log's frames
};

/// How the caller names an option, given its name here ("time_unit", "fill"): "--time-unit" and
/// "--no-fill" in the program, "time_unit" and "fill=False" in Python.
using OptionNamer = std::function<std::string(std::string_view)>;

/// The options for the log at `path` ("-": standard input): its format detected unless given, a
/// TUM file's object named after the file, a MOTChallenge file's frame rate from its sequence's
/// seqinfo.ini (frameRate=, beside it or one folder up) unless given. Throws
/// std::invalid_argument naming the option as `name` does ("option '--time-unit': ...").
LogReadOptions log_read_options(const LogArguments& arguments, const std::string& path,
                                const OptionNamer& name);

}  // namespace opf
