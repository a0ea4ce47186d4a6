#include "opf/io/frame_assembler.h"

#include "opf/io/csv.h"
#include "opf/io/input_error.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace opf {
namespace {

/// Intervals between one object's detections needed before the units and the tolerance are
/// inferred; also enough rows, whatever they hold.
constexpr std::size_t kCalibrationIntervals = 8;
constexpr std::size_t kMaxCalibrationRows = 4096;
/// Frame intervals the gap period is the median of: enough to ignore a gap or two, few enough to
/// follow a rate that changes.
constexpr std::size_t kRecentIntervals = 31;
/// A frame interval longer than this many periods is a gap.
constexpr double kGapPeriods = 1.5;
/// The inferred tolerance as a share of the lower quartile of the intervals between one object's
/// detections: the quartile rather than the median, so that a detector that sees an object in
/// pairs or short bursts (half its intervals the gaps between them) still gives its frame period.
constexpr double kToleranceShare = 0.25;
constexpr double kToleranceQuantile = 0.25;

/// The element at `share` of the sorted values (0.5: the median, the upper one of an even count).
double quantile(std::vector<double> values, double share) {
  if (values.empty()) return 0.0;
  const auto at = values.begin() +
                  static_cast<std::ptrdiff_t>(share * static_cast<double>(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

double median(std::vector<double> values) {
  return quantile(std::move(values), 0.5);
}

std::string seconds_text(double seconds) {
  return csv::format_double(seconds) + " s";
}

/// The unit times look like, from the median interval between one object's detections.
TimeUnit unit_of_interval(double interval) {
  if (interval <= 1e4) return TimeUnit::kMilliseconds;
  if (interval <= 1e7) return TimeUnit::kMicroseconds;
  return TimeUnit::kNanoseconds;
}

/// The unit of epoch-like times, from their size (now is 1.8e9 s since 1970).
TimeUnit unit_of_epoch(double t) {
  if (t < 1e14) return TimeUnit::kMilliseconds;
  if (t < 1e17) return TimeUnit::kMicroseconds;
  return TimeUnit::kNanoseconds;
}

}  // namespace

FrameAssembler::FrameAssembler(std::string source, const LogReadOptions& options)
    : source_(std::move(source)),
      options_(options),
      t_column_(mapped_column(options, "t")),
      object_column_(mapped_column(options, "object")),
      position_columns_(mapped_column(options, "x") + "," + mapped_column(options, "y") + "," +
                        mapped_column(options, "z")) {}

void FrameAssembler::fail(std::size_t line, const std::string& column,
                          const std::string& message) const {
  throw InputError(source_, line, column, message);
}

void FrameAssembler::push(LogRow row) {
  ++report_.rows;
  if (calibrated_) {
    add(std::move(row));
    return;
  }
  ++pending_objects_[row.object];
  pending_.push_back(std::move(row));
  if (pending_.size() - pending_objects_.size() >= kCalibrationIntervals ||
      pending_.size() >= kMaxCalibrationRows)
    calibrate();
}

void FrameAssembler::finish() {
  if (!calibrated_) calibrate();
  if (open_) close_frame();
}

std::optional<Frame> FrameAssembler::pop() {
  if (ready_.empty()) return std::nullopt;
  Frame frame = std::move(ready_.front());
  ready_.pop_front();
  return frame;
}

// Infers from the first rows what the log does not say: whether its units are plausible and how
// far apart one frame's rows may be. Nothing is produced before, so a refusal comes first.
void FrameAssembler::calibrate() {
  calibrated_ = true;
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const LogRow& a, const LogRow& b) { return a.t < b.t; });
  std::vector<double> intervals;
  std::vector<double> speeds;
  std::size_t interval_line = 0;  // the first row that ends an interval
  std::map<std::string, const LogRow*> last;
  for (const LogRow& row : pending_) {
    const LogRow*& previous = last[row.object];
    if (previous && row.t > previous->t) {
      const double dt = row.t - previous->t;
      intervals.push_back(dt);
      if (interval_line == 0) interval_line = row.line;
      if (row.pose && previous->pose)
        speeds.push_back(std::hypot(row.pose->x() - previous->pose->x(),
                                    row.pose->y() - previous->pose->y(),
                                    row.pose->z() - previous->pose->z()) /
                         dt);
    }
    previous = &row;
  }
  object_interval_ = median(intervals);

  if (!stated_time_unit(options_) && !pending_.empty()) {
    const LogRow& first = pending_.front();
    if (std::abs(first.t) > 1e11) {
      const TimeUnit unit = unit_of_epoch(std::abs(first.t));
      fail(first.line, t_column_,
           "t = " + csv::format_double(first.t) +
               " cannot be seconds (past the year 5000); the times look like " +
               std::string(to_string(unit)) + " since 1970: pass --time-unit " +
               std::string(to_string(unit)) + " (or s, ms, us, ns: the unit of t)");
    }
    if (object_interval_ > kMaxPlausibleInterval) {
      const TimeUnit unit = unit_of_interval(object_interval_);
      fail(interval_line, t_column_,
           "one object's detections are a median " + csv::format_double(object_interval_) +
               " apart, which cannot be seconds (over " + seconds_text(kMaxPlausibleInterval) +
               "); the times look like " + std::string(to_string(unit)) + ": pass --time-unit " +
               std::string(to_string(unit)) + " (or s, ms, us, ns: the unit of t)");
    }
  }
  if (!options_.length_unit && !speeds.empty()) {
    const double speed = median(speeds);
    if (speed > kMaxPlausibleSpeed)
      fail(interval_line, position_columns_,
           "the objects move a median " + csv::format_double(speed) +
               " m/s between detections (over " + csv::format_double(kMaxPlausibleSpeed) +
               " m/s); the positions look like millimetres: pass --length-unit mm (or "
               "--length-unit m if they are metres)");
  }
  report_.frame_tolerance =
      options_.frame_tolerance.value_or(kToleranceShare * quantile(intervals, kToleranceQuantile));

  std::vector<LogRow> rows = std::move(pending_);
  pending_ = {};
  pending_objects_.clear();
  for (LogRow& row : rows) add(std::move(row));
}

void FrameAssembler::add(LogRow row) {
  const double tolerance = report_.frame_tolerance;
  if (open_) {
    const bool fits = row.t >= start_ - tolerance && row.t - start_ <= tolerance;
    if (const auto member = members_.find(row.object); member != members_.end()) {
      const auto [t, line] = member->second;
      if (t == row.t)
        fail(row.line, object_column_,
             "object '" + row.object + "' appears twice at t = " + csv::format_double(row.t) +
                 " (first on line " + std::to_string(line) + ")");
      if (fits)
        fail(row.line, t_column_,
             "object '" + row.object + "' has a second row " + seconds_text(std::abs(row.t - t)) +
                 " from its row on line " + std::to_string(line) + ", within the frame tolerance " +
                 seconds_text(tolerance) +
                 ": one frame cannot hold two detections of an object; pass a smaller "
                 "--frame-tolerance (0: only equal times share a frame)");
    }
    if (row.t < start_ - tolerance)
      fail(row.line, t_column_,
           "out of order: t = " + csv::format_double(row.t) +
               " comes after a row at t = " + csv::format_double(start_) +
               "; a stream must be in time order (a whole file read at once may be unsorted)");
    if (!fits) close_frame();
  }
  if (!open_) {
    if (last_frame_t_ && row.t <= *last_frame_t_)
      fail(row.line, t_column_,
           "out of order: t = " + csv::format_double(row.t) +
               " is not after the frame at t = " + csv::format_double(*last_frame_t_) +
               " already produced; a stream must be in time order (a whole file read at once may "
               "be unsorted)");
    // 1 ns less the rounding of a nanosecond clock's times read as seconds.
    if (last_frame_t_ && row.t - *last_frame_t_ < (1.0 - 1e-6) / kMaxFrameRate)
      fail(row.line, t_column_,
           "t = " + csv::format_double(row.t) + " is " + seconds_text(row.t - *last_frame_t_) +
               " after the frame at t = " + csv::format_double(*last_frame_t_) +
               ": frames under 1 ns apart (over " + csv::format_double(kMaxFrameRate) +
               " Hz) are no camera's; pass --frame-tolerance if these rows are one frame, or "
               "--time-unit if t is not in seconds");
    open_ = true;
    start_ = row.t;
    offset_sum_ = 0.0;
    frame_ = Frame{};
    members_.clear();
  }
  members_[row.object] = {row.t, row.line};
  offset_sum_ += row.t - start_;  // offsets, so that equal times give exactly that time
  if (row.pose)
    frame_.detections.push_back(
        {std::move(row.object), *row.pose, row.extra_noise, row.radius, row.box});
}

double FrameAssembler::gap_period() const {
  if (options_.rate) return 1.0 / *options_.rate;
  if (recent_intervals_.size() >= 3)
    return median({recent_intervals_.begin(), recent_intervals_.end()});
  return object_interval_;
}

void FrameAssembler::close_frame() {
  open_ = false;
  frame_.t = start_ + offset_sum_ / static_cast<double>(members_.size());
  if (last_frame_t_) {
    const double interval = frame_.t - *last_frame_t_;
    const double period = gap_period();
    if (options_.fill_gaps && period > 0.0 && interval > kGapPeriods * period) {
      if (interval > kMaxFilledGap || interval > kMaxFilledFrames * period) {
        ++report_.long_gaps;
      } else {
        const long missing = std::lround(interval / period) - 1;
        for (long k = 1; k <= missing; ++k) {
          Frame filled;
          filled.t =
              *last_frame_t_ + interval * static_cast<double>(k) / static_cast<double>(missing + 1);
          filled.filled = true;
          emit(std::move(filled));
          ++report_.filled_frames;
        }
        if (missing > 0) ++report_.gaps;
      }
    }
    recent_intervals_.push_back(interval);
    if (recent_intervals_.size() > kRecentIntervals) recent_intervals_.pop_front();
    report_.frame_period = gap_period();
  }
  last_frame_t_ = frame_.t;
  emit(std::move(frame_));  // the next row's add() starts a fresh frame_
}

void FrameAssembler::emit(Frame frame) {
  ++report_.frames;
  ready_.push_back(std::move(frame));
}

}  // namespace opf
