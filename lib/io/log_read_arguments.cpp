#include "opf/io/log_read_arguments.h"

#include "opf/io/csv.h"
#include "opf/io/log_format_detection.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace opf {
namespace {

[[noreturn]] void refuse(const std::string& option, const std::string& message) {
  throw std::invalid_argument("option '" + option + "'" + message);
}

// The frame rate of a MOTChallenge file: its sequence's seqinfo.ini (frameRate=), beside it or
// one folder up (MOT17-02/gt/gt.txt).
std::optional<double> box_frame_rate(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (const auto& info : {folder / "seqinfo.ini", folder.parent_path() / "seqinfo.ini"}) {
    std::ifstream in(info);
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.rfind("frameRate=", 0) != 0) continue;
      const auto rate = csv::parse_double(line.substr(10));
      if (rate && is_frame_rate(*rate)) return rate;
    }
  }
  return std::nullopt;
}

// The format (given or detected) and what it implies: a TUM file's object, the options a
// MOTChallenge file's ids, pixels and frame numbers leave no room for.
void read_format(const LogArguments& a, const std::string& path, const OptionNamer& name,
                 LogReadOptions& options) {
  if (a.format) {
    const auto parsed = parse_log_format(*a.format);
    if (!parsed)
      refuse(name("format"), ": expected csv, tum, mot, euroc or kitti, got \"" + *a.format + "\"");
    options.format = *parsed;
  } else if (path != "-") {
    options.format = detect_log_format(path);
  }
  if (a.object && a.object->empty()) refuse(name("object"), " expects a name, got an empty one");
  options.object = a.object;
  if (is_one_object_format(options.format) && !options.object) {
    if (path == "-")
      throw std::invalid_argument(
          std::string(options.format == LogFormat::kTum ? "a TUM" : "an ASL") +
          " log on standard input needs its object's name: " + name("object") + " NAME");
    options.object = std::filesystem::path(path).stem().string();
  }
  if (options.format != LogFormat::kCsv && a.columns)
    refuse(name("columns"),
           " renames CSV columns; a TUM, MOTChallenge, ASL or KITTI file's columns are its "
           "format's");
  if (!is_frame_numbered_format(options.format)) return;
  const std::string what = options.format == LogFormat::kMot
                               ? "a MOTChallenge file (ids, pixels, frame numbers)"
                               : "a KITTI tracking file (ids, metres, frame numbers)";
  for (const auto& [given, option] : {std::pair{a.object.has_value(), "object"},
                                      {a.time_unit.has_value(), "time_unit"},
                                      {a.length_unit.has_value(), "length_unit"}})
    if (given) refuse(name(option), " does not apply to " + what);
}

void read_units(const LogArguments& a, const OptionNamer& name, LogReadOptions& options) {
  if (a.time_unit) {
    options.time_unit = parse_time_unit(*a.time_unit);
    if (!options.time_unit)
      refuse(name("time_unit"), ": expected s, ms, us or ns, got \"" + *a.time_unit + "\"");
  }
  if (a.length_unit) {
    options.length_unit = parse_length_unit(*a.length_unit);
    if (!options.length_unit)
      refuse(name("length_unit"), ": expected m or mm, got \"" + *a.length_unit + "\"");
  }
  if (a.columns) {
    try {
      options.columns = parse_column_mapping(*a.columns);
    } catch (const std::invalid_argument& e) {
      refuse(name("columns"), ": " + std::string(e.what()));
    }
  }
}

}  // namespace

LogReadOptions log_read_options(const LogArguments& a, const std::string& path,
                                const OptionNamer& name) {
  LogReadOptions options;
  read_format(a, path, name, options);
  read_units(a, name, options);
  if (a.frame_tolerance) {
    if (!(*a.frame_tolerance >= 0.0) || !std::isfinite(*a.frame_tolerance))
      refuse(name("frame_tolerance"), " expects seconds >= 0");
    options.frame_tolerance = *a.frame_tolerance;
  }
  if (a.rate) {
    if (!is_frame_rate(*a.rate))
      refuse(name("rate"), " expects " + std::string(kFrameRateExpectation));
    options.rate = *a.rate;
  }
  options.fill_gaps = a.fill;
  // A MOTChallenge or KITTI file's rate times its frame numbers, whether gaps are filled or not.
  if (options.format == LogFormat::kMot) {
    if (!options.rate) options.rate = box_frame_rate(path);
    if (!options.rate)
      throw std::invalid_argument(
          "a MOTChallenge file's frame numbers need the frame rate: " + name("rate") +
          " HZ, or the sequence's seqinfo.ini beside the file or one "
          "folder up");
  } else if (options.format == LogFormat::kKitti) {
    if (!options.rate)
      throw std::invalid_argument("a KITTI tracking file's frame numbers need the frame rate: " +
                                  name("rate") + " HZ (10 for KITTI's own recordings)");
  } else if (!options.fill_gaps && options.rate) {
    throw std::invalid_argument("options '" + name("rate") + "' and '" + name("fill") +
                                "' contradict each other: " + name("rate") +
                                " sets the rate gaps are filled at");
  }
  return options;
}

}  // namespace opf
