#pragma once
// The measurement-log contract: how users replay their detections (AprilTag, mocap, any pose
// tracker) through the estimators. A CSV file, one row per detection, read into Frames.
//
// Format. A header line naming at least the columns
//   t,object,x,y,z,qx,qy,qz,qw
// in any order (other columns are ignored), then one row per detection: t in seconds, the object's
// name, its position in metres and its orientation as a unit quaternion (x, y, z, w). For example
//   t,object,x,y,z,qx,qy,qz,qw
//   0.000000,ball,0.400000,-0.200000,0.020000,0.000000000,0.000000000,0.000000000,1.000000000
//   0.033333,ball,,,,,,,
// Frames are the distinct values of t (compared exactly) in increasing order; rows may come in
// any order and keep their row order within a frame. An object is unobserved in a frame when it has
// no row at that t or a row with all seven pose fields empty (the frame exists either way).
// Quaternions within 0.01 of unit norm are normalised; the rest are rejected. A UTF-8 BOM, CRLF
// line ends, blank lines, whitespace around fields and double-quoted fields are accepted.

#include "core/frame.h"

#include <filesystem>
#include <istream>
#include <string>
#include <vector>

namespace opf {

struct MeasurementLog {
  std::vector<Frame> frames;  ///< increasing t
  /// Every detected object once, in order of first detection (by time, then row order).
  std::vector<std::string> objects;
};

/// Reads the log at `path`. Throws InputError naming the file, line and column of the first
/// problem, also when the file cannot be opened.
MeasurementLog read_measurement_log(const std::filesystem::path& path);

/// Parses a log from `in`; `source_name` is the file name used in error messages.
MeasurementLog parse_measurement_log(std::istream& in, const std::string& source_name);

}  // namespace opf
