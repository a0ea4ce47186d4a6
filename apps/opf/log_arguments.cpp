#include "log_arguments.h"

#include "opf/io/csv.h"
#include "opf/io/log_format_detection.h"
#include "opf/io/quaternion_order_check.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

namespace opf::cli {
namespace {

// A MOTChallenge file's ids name its objects, its pixels are its unit and its frame numbers its
// clock: the options that would say otherwise do not apply.
void refuse_options_for_boxes(const Arguments& args) {
  for (const char* option : {"object", "time-unit", "length-unit"})
    if (args.has(option))
      throw UsageError{"option '--" + std::string(option) +
                       "' does not apply to a MOTChallenge file (ids, pixels, frame numbers)"};
}

// The frame rate of a MOTChallenge file: its sequence's seqinfo.ini (frameRate=), beside it or
// one folder up (MOT17-02/gt/gt.txt).
double box_frame_rate(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (const auto& info : {folder / "seqinfo.ini", folder.parent_path() / "seqinfo.ini"}) {
    std::ifstream in(info);
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.rfind("frameRate=", 0) != 0) continue;
      const auto rate = csv::parse_double(line.substr(10));
      if (rate && *rate > 0.0) return *rate;
    }
  }
  throw UsageError{
      "a MOTChallenge file's frame numbers need the frame rate: --rate HZ, or the "
      "sequence's seqinfo.ini beside the file or one folder up"};
}

// --format (or what the file looks like) and what it implies: the object of a TUM file, the
// options a MOTChallenge file refuses.
void read_format(const Arguments& args, const std::string& path, LogReadOptions& options) {
  if (const auto format = args.get("format")) {
    const auto parsed = parse_log_format(*format);
    if (!parsed)
      throw UsageError{"option '--format': expected csv, tum or mot, got \"" + *format + "\""};
    options.format = *parsed;
  } else if (path != "-") {
    options.format = detect_log_format(path);
  }
  options.object = args.get("object");
  if (options.object && options.object->empty())
    throw UsageError{"option '--object' expects a name, got an empty one"};
  if (options.format == LogFormat::kTum && !options.object) {
    if (path == "-")
      throw UsageError{"a TUM log on standard input needs its object's name: --object NAME"};
    options.object = std::filesystem::path(path).stem().string();
  }
  if (options.format != LogFormat::kCsv && args.has("columns"))
    throw UsageError{"option '--columns' renames CSV columns; a TUM or MOTChallenge file has none"};
  if (options.format == LogFormat::kMot) refuse_options_for_boxes(args);
}

}  // namespace

std::vector<OptionSpec> log_option_specs() {
  return {
      {"format", "csv|tum|mot",
       "the log's format (default: TUM for a file starting with a '#' line, named *.tum, or *.txt "
       "with eight numbers per line; MOTChallenge boxes for a *.txt of comma-separated numbers; "
       "CSV otherwise)"},
      {"object", "NAME",
       "the object of a log of one object without an object column (default for a TUM file: "
       "its name without the extension)"},
      {"time-unit", "s|ms|us|ns",
       "unit of the log's t (default s; a log whose times cannot be seconds is refused)"},
      {"length-unit", "m|mm",
       "unit of the log's x, y, z (default m; objects faster than 100 m/s are refused as mm)"},
      {"columns", "NAME=COL,...",
       "the log's own column names, e.g. qx=rx,qy=ry,qz=rz,qw=rw (default: the format's names)"},
      {"frame-tolerance", "S",
       "rows this close in time (s) form one frame (default: a quarter of the median interval "
       "between one object's detections; 0: equal times only)"},
      {"rate", "HZ", "frame rate at which gaps in the log are filled (default: inferred from it)"},
      {"no-fill", "", "keep only the log's frames: no estimates inside gaps"},
  };
}

LogReadOptions log_options_from(const Arguments& args, const std::string& path) {
  LogReadOptions options;
  read_format(args, path, options);
  if (const auto unit = args.get("time-unit")) {
    options.time_unit = parse_time_unit(*unit);
    if (!options.time_unit)
      throw UsageError{"option '--time-unit': expected s, ms, us or ns, got \"" + *unit + "\""};
  }
  if (const auto unit = args.get("length-unit")) {
    options.length_unit = parse_length_unit(*unit);
    if (!options.length_unit)
      throw UsageError{"option '--length-unit': expected m or mm, got \"" + *unit + "\""};
  }
  if (const auto columns = args.get("columns")) {
    try {
      options.columns = parse_column_mapping(*columns);
    } catch (const std::invalid_argument& e) {
      throw UsageError{"option '--columns': " + std::string(e.what())};
    }
  }
  if (const auto tolerance = args.get_number("frame-tolerance")) {
    if (*tolerance < 0.0) throw UsageError{"option '--frame-tolerance' expects seconds >= 0"};
    options.frame_tolerance = *tolerance;
  }
  if (const auto rate = args.get_number("rate")) {
    if (!(*rate > 0.0)) throw UsageError{"option '--rate' expects a frame rate in Hz > 0"};
    options.rate = *rate;
  }
  options.fill_gaps = !args.has("no-fill");
  if (options.format == LogFormat::kMot && !options.rate) options.rate = box_frame_rate(path);
  if (!options.fill_gaps && options.rate)
    throw UsageError{
        "options '--rate' and '--no-fill' contradict each other: --rate sets the "
        "rate gaps are filled at"};
  return options;
}

MeasurementLog read_whole_log(const std::string& path, const LogReadOptions& options,
                              const std::string& command, bool quiet) {
  MeasurementLog log = read_measurement_log(path, options);
  if (!quiet)
    for (const std::string& object : objects_with_w_first_quaternions(log))
      std::cerr << "opf " << command << ": warning: " << path << ": "
                << w_first_warning(object, options.format) << "\n";
  return log;
}

}  // namespace opf::cli
