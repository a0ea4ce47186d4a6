#include "log_arguments.h"

#include "opf/io/log_read_arguments.h"
#include "opf/io/quaternion_order_check.h"

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace opf::cli {
namespace {

// The program's name of a log option: --time-unit for time_unit, --no-fill for fill.
std::string program_name(std::string_view option) {
  if (option == "fill") return "--no-fill";
  std::string name = "--" + std::string(option);
  std::replace(name.begin(), name.end(), '_', '-');
  return name;
}

}  // namespace

std::vector<OptionSpec> log_option_specs() {
  return {
      {"format", "csv|tum|mot|euroc|kitti",
       "the log's format (default: for a file starting with a '#' line, EuRoC's ASL CSV if its "
       "first other line is comma-separated numbers, else TUM; TUM for *.tum, or *.txt with "
       "eight numbers per line; MOTChallenge boxes for a *.txt of comma-separated numbers; KITTI "
       "tracking labels for a *.txt of them; CSV otherwise)"},
      {"object", "NAME",
       "the object of a log of one object without an object column (default for a TUM or ASL "
       "file: its name without the extension)"},
      {"time-unit", "s|ms|us|ns",
       "unit of the log's t (default s; a log whose times cannot be seconds is refused)"},
      {"length-unit", "m|mm",
       "unit of the log's x, y, z (default m; objects faster than 100 m/s are refused as mm)"},
      {"columns", "NAME=COL,...",
       "the log's own column names, e.g. qx=rx,qy=ry,qz=rz,qw=rw (default: the format's names)"},
      {"frame-tolerance", "S",
       "rows this close in time (s) form one frame (default: a quarter of the lower quartile of "
       "the intervals between one object's detections; 0: equal times only)"},
      {"rate", "HZ",
       "frame rate at which gaps in the log are filled (default: inferred from it); a MOTChallenge "
       "or KITTI file's frame numbers are timed by it"},
      {"no-fill", "", "keep only the log's frames: no estimates inside gaps"},
  };
}

LogReadOptions log_options_from(const Arguments& args, const std::string& path) {
  LogArguments given;
  given.format = args.get("format");
  given.object = args.get("object");
  given.time_unit = args.get("time-unit");
  given.length_unit = args.get("length-unit");
  given.columns = args.get("columns");
  given.frame_tolerance = args.get_number("frame-tolerance");
  given.rate = args.get_number("rate");
  given.fill = !args.has("no-fill");
  try {
    return log_read_options(given, path, program_name);
  } catch (const std::invalid_argument& e) {
    throw UsageError{e.what()};
  }
}

MeasurementLog read_whole_log(const std::string& path, const LogReadOptions& options,
                              const std::string& command, bool quiet) {
  MeasurementLog log = read_measurement_log(path, options);
  if (quiet) return log;
  for (const std::string& object : objects_with_w_first_quaternions(log))
    std::cerr << "opf " << command << ": warning: " << path << ": "
              << w_first_warning(object, options.format) << "\n";
  if (!log.states_orientation) note_positions_only(command, path);
  return log;
}

void note_positions_only(const std::string& command, const std::string& path) {
  std::cerr << "opf " << command << ": note: " << path << ": " << positions_only_note() << "\n";
}

}  // namespace opf::cli
