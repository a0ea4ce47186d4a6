#pragma once
// track_log's log options: opf track's --format, --object, --time-unit, --length-unit, --columns,
// --frame-tolerance, --rate and --no-fill, mapped onto LogReadOptions by the function the program
// uses (io/log_read_arguments.h): the same meanings, defaults, checks and words.

#include "opf/io/log_read_options.h"

#include <pybind11/pybind11.h>

#include <optional>
#include <string>

namespace opf::python {

struct LogArguments {
  std::optional<std::string> format;       ///< csv or tum; None: detected from the file
  std::optional<std::string> object;       ///< the one object of a log without an object column
  std::optional<std::string> time_unit;    ///< s, ms, us or ns; None: s, checked
  std::optional<std::string> length_unit;  ///< m or mm; None: m, checked
  /// None, {"qx": "rx", ...} or opf track's text "qx=rx,...".
  pybind11::object columns = pybind11::none();
  std::optional<double> frame_tolerance;  ///< s >= 0; None: inferred
  std::optional<double> rate;             ///< Hz > 0; None: inferred
  bool fill = true;                       ///< false: opf track --no-fill
};

/// The options for the log at `path`; throws std::invalid_argument (ValueError) naming the option
/// of a bad value.
LogReadOptions log_options_from(const LogArguments& arguments, const std::string& path);

}  // namespace opf::python
