#pragma once
// How a measurement log is read when it was not written the way the toolkit writes its own: the
// units of its times and positions, its column names, how far apart the clocks of one frame's
// detections may be, and whether frames missing inside gaps are filled.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace opf {

/// The columns of the log format, in this order: t, object, the position, the quaternion.
inline constexpr std::array<std::string_view, 9> kLogColumns = {"t",  "object", "x",  "y", "z",
                                                                "qx", "qy",     "qz", "qw"};
/// A CSV log's optional column: the extra noise the detector states for each detection (m, a
/// standard deviation >= 0; empty: none), Detection::extra_noise.
inline constexpr std::string_view kExtraNoiseColumn = "extra_noise";
/// A CSV log's optional column: the object's extent across the line of sight as the detector
/// states it (m, a radius >= 0; empty: not stated), Detection::radius.
inline constexpr std::string_view kRadiusColumn = "radius";
/// A CSV log's optional columns: the full extents of the object's bounding box in its own frame
/// as the detector states them (m, each > 0; all three empty: not stated), Detection::box.
inline constexpr std::array<std::string_view, 3> kBoxColumns = {"box_x", "box_y", "box_z"};

/// kCsv: the toolkit's CSV (a header naming kLogColumns). kTum: the TUM RGB-D trajectory format
/// (evo, most SLAM systems): "timestamp tx ty tz qx qy qz qw" per line, separated by spaces or
/// tabs, '#' starting a comment line; one object. kMot: MOTChallenge's 2-D boxes
/// (kMotColumns and more, no header; gt.txt, det.txt and trackers' results): each box becomes
/// the pose of its bottom centre in the image plane (kMetresPerPixel), the track id its object.
/// kEuroc: the ASL CSV of the EuRoC and TUM VI datasets' ground truth and motion capture
/// (state_groundtruth_estimate0, vicon0, mocap0; Kalibr and OpenVINS write it too): '#' header
/// lines, then "timestamp, p_x, p_y, p_z, q_w, q_x, q_y, q_z" and any further columns, separated
/// by commas, the timestamp in nanoseconds and the quaternion w first; one object.
/// kKitti: the KITTI tracking benchmark's labels, and 3-D trackers' results in their format
/// (kKittiColumns and an optional score, separated by spaces): each box becomes the pose of its
/// centre in the camera's frame (x right, y down, z forward), turned by rotation_y about y, with
/// its extents as the detection's box, its track id the object, frame k the time k / rate.
enum class LogFormat { kCsv, kTum, kMot, kEuroc, kKitti };
/// The fields of a kTum line, in order.
inline constexpr std::array<std::string_view, 8> kTumColumns = {"timestamp", "tx", "ty", "tz",
                                                                "qx",        "qy", "qz", "qw"};

/// The first fields of a kEuroc line, in order (its header's names vary: they are not read).
inline constexpr std::array<std::string_view, 8> kEurocColumns = {"timestamp", "p_x", "p_y", "p_z",
                                                                  "q_w",       "q_x", "q_y", "q_z"};

/// Whether a format holds one object's poses (kTum, kEuroc): the object is named after the file,
/// or by LogReadOptions::object.
constexpr bool is_one_object_format(LogFormat format) {
  return format == LogFormat::kTum || format == LogFormat::kEuroc;
}

/// The fields of a kKitti line, in order (a results file adds a score).
inline constexpr std::array<std::string_view, 17> kKittiColumns = {
    "frame",     "track_id", "type",       "truncated",   "occluded",  "alpha",
    "bbox_left", "bbox_top", "bbox_right", "bbox_bottom", "height",    "width",
    "length",    "x",        "y",          "z",           "rotation_y"};

/// Whether a format's rows give frame numbers, which LogReadOptions::rate turns into times (kMot,
/// kKitti), rather than times.
constexpr bool is_frame_numbered_format(LogFormat format) {
  return format == LogFormat::kMot || format == LogFormat::kKitti;
}

/// The first fields of a kMot line, in order.
inline constexpr std::array<std::string_view, 7> kMotColumns = {
    "frame", "id", "bb_left", "bb_top", "bb_width", "bb_height", "conf"};
/// A MOTChallenge box's pixels as metres: 1 px is 1 mm, so image motion keeps plausible speeds.
inline constexpr double kMetresPerPixel = 0.001;

enum class TimeUnit { kSeconds, kMilliseconds, kMicroseconds, kNanoseconds };
enum class LengthUnit { kMetres, kMillimetres };

struct LogReadOptions {
  LogFormat format = LogFormat::kCsv;
  /// The one object every row is of, for a log without an object column (required for kTum and
  /// kEuroc; with kCsv, the file then must have no object column).
  std::optional<std::string> object;
  /// The unit of t. Unset: seconds, and a log whose times cannot be seconds (one object detected
  /// less often than every 10 s, or epoch-like values past the year 5000) is refused with the unit
  /// they look like.
  std::optional<TimeUnit> time_unit;
  /// The unit of x, y, z. Unset: metres, and a log whose objects move faster than
  /// kMaxPlausibleSpeed between detections (median) is refused as millimetres.
  std::optional<LengthUnit> length_unit;
  /// Rows this close in time (seconds) belong to one frame. Unset: a quarter of the lower quartile
  /// of the intervals between one object's detections; 0: only equal times share a frame.
  std::optional<double> frame_tolerance;
  /// Column names of the file for the canonical ones (t, object, x, y, z, qx, qy, qz, qw), e.g.
  /// {"qx", "rx"}; columns not named keep their canonical name.
  std::vector<std::pair<std::string, std::string>> columns;
  /// Insert empty frames where the log has none for longer than 1.5 frame periods.
  bool fill_gaps = true;
  /// The frame rate (Hz) gaps are filled at. Unset: the median of the recent frame intervals.
  /// Required for kMot, whose frame numbers it turns into times: t = (frame - 1) / rate.
  std::optional<double> rate;
};

/// Objects faster than this (m/s, median between detections) are taken as logged in millimetres.
inline constexpr double kMaxPlausibleSpeed = 100.0;
/// One object's detections further apart than this (s, median) are taken as not in seconds.
inline constexpr double kMaxPlausibleInterval = 10.0;
/// Hz: the lowest frame rate a command takes (--rate), frames at most kMaxPlausibleInterval
/// apart; a log at a lower rate would be refused as not in seconds.
inline constexpr double kMinFrameRate = 1.0 / kMaxPlausibleInterval;
/// Hz: the highest, frames 1 ns apart: the finest clock a log format here stores (EuRoC's integer
/// nanoseconds); no camera or motion-capture system comes near it.
inline constexpr double kMaxFrameRate = 1e9;
/// Whether `hz` is a frame rate a command takes: within [kMinFrameRate, kMaxFrameRate].
inline constexpr bool is_frame_rate(double hz) {
  return hz >= kMinFrameRate && hz <= kMaxFrameRate;
}
/// What an error says a rate must be, wherever is_frame_rate is checked.
inline constexpr std::string_view kFrameRateExpectation =
    "a frame rate in Hz from 0.1 to 1e9 (frames 10 s to 1 ns apart)";
/// Gaps longer than this (s) are not filled (reported instead): a clock jump, not a dropout.
inline constexpr double kMaxFilledGap = 10.0;
/// More frames than this in one gap are not filled either: a period of microseconds over seconds
/// is not a frame rate (and would fill without bound).
inline constexpr double kMaxFilledFrames = 1e5;

/// "csv", "tum", "mot", "euroc", "kitti": the names of --format.
std::optional<LogFormat> parse_log_format(std::string_view name);

/// "s", "ms", "us", "ns" and "m", "mm": the names the command line and the settings file use.
std::optional<TimeUnit> parse_time_unit(std::string_view name);
std::optional<LengthUnit> parse_length_unit(std::string_view name);
std::string_view to_string(TimeUnit unit);
std::string_view to_string(LengthUnit unit);
/// Seconds per unit, metres per unit.
double seconds_per(TimeUnit unit);
double metres_per(LengthUnit unit);

/// The unit of t as stated: options.time_unit, else nanoseconds for kEuroc (its format's), else
/// none (seconds, checked for plausibility).
std::optional<TimeUnit> stated_time_unit(const LogReadOptions& options);

/// The file's name of the canonical column `canonical` under `options.columns`.
std::string mapped_column(const LogReadOptions& options, std::string_view canonical);

/// "qx=rx,qy=ry" -> {{"qx", "rx"}, {"qy", "ry"}}. Throws std::invalid_argument naming the entry
/// when one is not NAME=COLUMN, names no canonical column, or maps a column twice.
std::vector<std::pair<std::string, std::string>> parse_column_mapping(std::string_view text);

}  // namespace opf
