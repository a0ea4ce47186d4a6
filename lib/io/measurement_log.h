#pragma once
// The measurement-log contract: how users replay their detections (AprilTag, mocap, any pose
// tracker) through the estimators. A CSV file, one row per detection (t,object,x,y,z,qx,qy,qz,qw),
// read into Frames: rows close in time form one frame, an object without a row (or with empty pose
// fields) is unobserved there, frames missing inside a gap are inserted, empty and marked filled.
// The format is documented in one place, docs/formats.md; frames, units, gaps and streams from
// real systems in docs/logs.md.

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
  /// False for a log of positions alone: every detection's orientation is the identity
  /// (LogRowReader::states_orientation).
  bool states_orientation = true;
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
  /// As MeasurementLog::states_orientation.
  bool states_orientation() const { return rows_.states_orientation(); }

 private:
  LogRowReader rows_;
  FrameAssembler assembler_;
  std::string source_;
  bool finished_ = false;
  bool any_detection_ = false;
};

}  // namespace opf
