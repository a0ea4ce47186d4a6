#pragma once
// Turns detection rows into Frames the way real clocks need it: rows close in time form one frame
// (each sensor stamps its own detections), implausible units are refused before anything is
// produced, and frames missing inside gaps are inserted. Incremental, so that a stream is answered
// frame by frame with memory bounded by the number of objects; reading a whole file feeds it the
// rows sorted by time and gets the same frames.

#include "opf/core/frame.h"
#include "opf/io/log_read_options.h"
#include "opf/io/log_row_reader.h"

#include <cstddef>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace opf {

/// What the assembler inferred and did, for the user and for evaluation.
struct FrameAssemblyReport {
  std::size_t rows = 0;
  std::size_t frames = 0;         ///< frames out, filled ones included
  std::size_t filled_frames = 0;  ///< frames inserted inside gaps
  std::size_t gaps = 0;           ///< gaps filled
  std::size_t long_gaps =
      0;  ///< gaps longer than kMaxFilledGap or kMaxFilledFrames periods, left unfilled
  double frame_tolerance = 0.0;  ///< seconds, as given or inferred
  double frame_period = 0.0;     ///< seconds, the latest gap-filling period (0 before known)
};

class FrameAssembler {
 public:
  FrameAssembler(std::string source, const LogReadOptions& options);

  /// Adds a row. Rows must come in time order, except within the open frame's tolerance and
  /// before the first frame is out (the rows needed to infer the units and the tolerance, which
  /// are sorted). Throws InputError at the row's line for a duplicate, a row whose frame has
  /// already been produced (out of order), or implausible units.
  void push(LogRow row);
  /// No more rows: closes the open frame (and infers what was not yet inferred).
  void finish();
  /// The next completed frame, oldest first; nullopt when none is ready.
  std::optional<Frame> pop();

  const FrameAssemblyReport& report() const { return report_; }

 private:
  void calibrate();
  void add(LogRow row);
  void close_frame();
  void emit(Frame frame);
  double gap_period() const;
  [[noreturn]] void fail(std::size_t line, const std::string& column,
                         const std::string& message) const;

  std::string source_;
  LogReadOptions options_;
  // The file's names of the columns errors point at.
  std::string t_column_;
  std::string object_column_;
  std::string position_columns_;  // "x,y,z"
  FrameAssemblyReport report_;

  // Until calibrated: the rows so far and the objects they name.
  bool calibrated_ = false;
  std::vector<LogRow> pending_;
  std::map<std::string, std::size_t> pending_objects_;
  double object_interval_ = 0.0;  // median interval of one object's detections, 0 when none

  // The open frame: its first time, the rows' offsets from it and their lines by object.
  bool open_ = false;
  double start_ = 0.0;
  double offset_sum_ = 0.0;
  Frame frame_;
  std::map<std::string, std::pair<double, std::size_t>> members_;  // object -> (t, line)

  std::optional<double> last_frame_t_;
  std::deque<double> recent_intervals_;  // the last frame intervals, for the gap period
  std::deque<Frame> ready_;
};

}  // namespace opf
