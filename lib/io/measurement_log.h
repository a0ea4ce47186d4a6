#pragma once
// The measurement-log contract: how users replay their detections (AprilTag, mocap, any pose
// tracker) through the estimators. A CSV file, one row per detection, read into Frames.
//
// Format. A header line naming at least the columns
//   t,object,x,y,z,qx,qy,qz,qw
// in any order (other columns are ignored; LogReadOptions::columns maps other names), then one row
// per detection: t in seconds, the object's name, its position in metres and its orientation as a
// unit quaternion (x, y, z, w). For example
//   t,object,x,y,z,qx,qy,qz,qw
//   0.000000,ball,0.400000,-0.200000,0.020000,0.000000000,0.000000000,0.000000000,1.000000000
//   0.033333,ball,,,,,,,
// Frames. Rows close in time form one frame: within the frame tolerance (by default a quarter of
// the median interval between one object's detections, so that sensors stamping their own
// detections a fraction of a millisecond apart still share a frame), at the mean of its rows'
// times; equal times always share one. An object is unobserved in a frame when it has no row
// there or a row with all seven pose fields empty (the frame exists either way). Frames missing
// inside a gap (no row for more than 1.5 frame periods) are inserted, empty and marked filled.
// A whole file may list its rows in any order; a stream must be in time order.
// Quaternions within 0.01 of unit norm are normalised; the rest are rejected. A UTF-8 BOM, CRLF
// line ends, blank lines, whitespace around fields and double-quoted fields are accepted. Times
// that cannot be seconds and positions that cannot be metres are refused unless their unit is
// given (LogReadOptions).

#include "opf/core/frame.h"
#include "opf/io/frame_assembler.h"
#include "opf/io/log_read_options.h"
#include "opf/io/log_row_reader.h"

#include <filesystem>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace opf {

struct MeasurementLog {
  std::vector<Frame> frames;  ///< increasing t
  /// Every detected object once, in order of first detection (by time, then row order).
  std::vector<std::string> objects;
  FrameAssemblyReport report;
};

/// Reads the log at `path`. Throws InputError naming the file, line and column of the first
/// problem, also when the file cannot be opened.
MeasurementLog read_measurement_log(const std::filesystem::path& path,
                                    const LogReadOptions& options = {});

/// Parses a log from `in`; `source_name` is the file name used in error messages.
MeasurementLog parse_measurement_log(std::istream& in, const std::string& source_name,
                                     const LogReadOptions& options = {});

/// A log read row by row as it arrives (a pipe, standard input): each frame is returned as soon
/// as the first row of the next one has been read, and memory stays bounded by the number of
/// objects. Rows must come in time order (FrameAssembler); the frames are those
/// parse_measurement_log gives for the same rows.
class MeasurementStream {
 public:
  MeasurementStream(std::istream& in, const std::string& source_name,
                    const LogReadOptions& options = {});

  /// The next frame; nullopt at the end of input. Throws InputError as parse_measurement_log,
  /// including "no detections" at the end of an input that had none.
  std::optional<Frame> next();

  const FrameAssemblyReport& report() const { return assembler_.report(); }

 private:
  LogRowReader rows_;
  FrameAssembler assembler_;
  std::string source_;
  bool finished_ = false;
  bool any_detection_ = false;
};

}  // namespace opf
