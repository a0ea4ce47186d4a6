#include "opf/io/log_row_reader.h"

#include "opf/core/option_schema.h"
#include "opf/core/pose_conversion.h"
#include "opf/io/input_error.h"
#include "opf/io/kitti_tracking_row.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace opf {
namespace {

constexpr std::size_t kPoseFields = 7;  // x, y, z, qx, qy, qz, qw: kLogColumns[2..8]
constexpr std::size_t kPositionFields = 3;
constexpr std::size_t kFirstQuaternionColumn = 5;  // qx in kLogColumns
constexpr double kQuaternionNormTolerance = 0.01;

// The file's names of t, object, x, y, z, qx, qy, qz, qw; the object's empty when the log has no
// object column.
std::array<std::string, 9> file_names(const LogReadOptions& options) {
  std::array<std::string, 9> names;
  // kMotColumns, kKittiColumns: read by read_mot_row(), read_kitti_tracking_row().
  if (is_frame_numbered_format(options.format)) return names;
  if (options.format == LogFormat::kTum) {
    names = {std::string(kTumColumns[0]), ""};
    for (std::size_t i = 1; i < kTumColumns.size(); ++i) names[i + 1] = kTumColumns[i];
    return names;
  }
  if (options.format == LogFormat::kEuroc) {  // t, -, p_x, p_y, p_z, q_x, q_y, q_z, q_w
    const auto& c = kEurocColumns;
    names = {std::string(c[0]), "",
             std::string(c[1]), std::string(c[2]),
             std::string(c[3]), std::string(c[5]),
             std::string(c[6]), std::string(c[7]),
             std::string(c[4])};
    return names;
  }
  for (std::size_t i = 0; i < kLogColumns.size(); ++i)
    names[i] = mapped_column(options, kLogColumns[i]);
  if (options.object) names[1].clear();
  return names;
}

csv::Reader open_reader(std::istream& in, const std::string& source, const LogReadOptions& options,
                        const std::array<std::string, 9>& names) {
  if (options.format == LogFormat::kMot)
    return csv::Reader(in, source,
                       csv::Reader::Headerless{{kMotColumns.begin(), kMotColumns.end()}, false});
  if (options.format == LogFormat::kTum)
    return csv::Reader(in, source,
                       csv::Reader::Headerless{{kTumColumns.begin(), kTumColumns.end()}});
  if (options.format == LogFormat::kKitti)  // a results file adds a score
    return csv::Reader(
        in, source,
        csv::Reader::Headerless{{kKittiColumns.begin(), kKittiColumns.end()}, true, true, 1});
  if (options.format == LogFormat::kEuroc)
    return csv::Reader(
        in, source,
        csv::Reader::Headerless{{kEurocColumns.begin(), kEurocColumns.end()}, false, true});
  // A log of positions leaves out all four of the quaternion's columns, unless --columns names one.
  std::vector<std::string_view> required;
  for (std::size_t i = 0; i < kFirstQuaternionColumn; ++i)
    if (!names[i].empty()) required.push_back(names[i]);
  csv::ColumnGroup quaternion;
  quaternion.names.assign(names.begin() + kFirstQuaternionColumn, names.end());
  const auto first = kLogColumns.begin() + kFirstQuaternionColumn;
  quaternion.required = std::any_of(options.columns.begin(), options.columns.end(), [&](auto& c) {
    return std::find(first, kLogColumns.end(), c.first) != kLogColumns.end();
  });
  return csv::Reader(in, source, required, quaternion);
}

}  // namespace

std::string positions_only_note() {
  return "it states positions only (no qx, qy, qz, qw columns): every detection's orientation is "
         "read as the identity, so the estimated orientations and rotation errors say nothing "
         "about the objects";
}

LogRowReader::LogRowReader(std::istream& in, const std::string& source,
                           const LogReadOptions& options)
    : format_(options.format),
      names_(file_names(options)),
      reader_(open_reader(in, source, options, names_)),
      object_(options.object.value_or("")),
      seconds_per_unit_(stated_time_unit(options) ? seconds_per(*stated_time_unit(options)) : 1.0),
      metres_per_unit_(options.length_unit ? metres_per(*options.length_unit) : 1.0) {
  if (is_frame_numbered_format(options.format)) {
    if (!options.rate)
      throw std::invalid_argument(
          std::string(options.format == LogFormat::kMot ? "a MOTChallenge" : "a KITTI tracking") +
          " file needs its frame rate to time its frames");
    box_frame_period_ = 1.0 / *options.rate;
    return;
  }
  if (names_[1].empty() && object_.empty())
    throw std::invalid_argument("a log without an object column needs the object's name");
  const std::string& object_column = mapped_column(options, "object");
  if (options.format == LogFormat::kCsv && options.object &&
      std::find(reader_.header().begin(), reader_.header().end(), object_column) !=
          reader_.header().end())
    throw InputError(source, reader_.line(), object_column,
                     "the log has an object column, so every row names its object: drop the "
                     "object's name (--object) or the column");
  if (options.format == LogFormat::kCsv && !reader_.has_column(names_[kFirstQuaternionColumn])) {
    states_orientation_ = false;
    for (std::size_t i = kFirstQuaternionColumn; i < names_.size(); ++i) names_[i].clear();
  }
  for (std::size_t i = 0; i < names_.size(); ++i)
    if (!names_[i].empty()) column_[i] = reader_.column(names_[i]);
  const auto optional_column = [&](std::string_view name) -> std::optional<std::size_t> {
    if (options.format != LogFormat::kCsv || !reader_.has_column(name)) return std::nullopt;
    return reader_.column(name);
  };
  extra_noise_column_ = optional_column(kExtraNoiseColumn);
  radius_column_ = optional_column(kRadiusColumn);
  for (std::size_t i = 0; i < kBoxColumns.size(); ++i)
    box_columns_[i] = optional_column(kBoxColumns[i]);
  const auto missing = std::find(box_columns_.begin(), box_columns_.end(), std::nullopt);
  const bool none = std::all_of(box_columns_.begin(), box_columns_.end(),
                                [](const auto& column) { return !column; });
  if (missing != box_columns_.end() && !none)
    throw InputError(
        source, reader_.line(),
        std::string(kBoxColumns[static_cast<std::size_t>(missing - box_columns_.begin())]),
        "missing: a box is stated by box_x, box_y and box_z together");
}

Eigen::Vector3d LogRowReader::read_box() const {
  if (!box_columns_[0]) return Eigen::Vector3d::Zero();
  std::size_t empty = 0;
  for (const auto& column : box_columns_) empty += reader_.field(*column).empty() ? 1 : 0;
  if (empty == 3) return Eigen::Vector3d::Zero();
  Eigen::Vector3d box;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t column = *box_columns_[i];
    if (reader_.field(column).empty())
      reader_.fail(column,
                   "empty while another of box_x, box_y, box_z is set; leave all three "
                   "empty where the box is not stated");
    const double value = reader_.number(column);
    if (!(value > 0.0))
      reader_.fail(column, "expected a box's extent > 0, got " + reader_.field(column));
    box(static_cast<Eigen::Index>(i)) = value * metres_per_unit_;
  }
  return box;
}

double LogRowReader::optional_length(const std::optional<std::size_t>& column,
                                     std::string_view what, double max_metres) const {
  if (!column || reader_.field(*column).empty()) return 0.0;
  const double value = reader_.number(*column);
  if (!(value >= 0.0))
    reader_.fail(*column, "expected " + std::string(what) + " >= 0, got " + reader_.field(*column));
  if (!(value * metres_per_unit_ <= max_metres))
    reader_.fail(*column, "expected " + std::string(what) + " up to " +
                              csv::format_double(max_metres) + " m, got " + reader_.field(*column));
  return value * metres_per_unit_;
}

// gt.txt has nine fields, its seventh a flag (0: a box the benchmark ignores, skipped); a
// detector's or a tracker's file has ten, the seventh a confidence. An id of -1 (det.txt) names no
// object.
bool LogRowReader::read_mot_row(LogRow& row) const {
  constexpr std::size_t kGroundTruthFields = 9;
  if (reader_.fields() == kGroundTruthFields && reader_.number(6) == 0.0) return false;
  row.line = reader_.line();
  const double frame = reader_.number(0);
  if (frame < 1.0 || frame != std::floor(frame))
    reader_.fail(0, "expected a frame number (1, 2, ...), got \"" + reader_.field(0) + "\"");
  row.t = (frame - 1.0) * box_frame_period_;
  const double id = reader_.number(1);
  if (id < 0.0)
    reader_.fail(1, "no track id (" + reader_.field(1) +
                        "): the tracker needs each box's object, as gt.txt and trackers' "
                        "results give it; det.txt's boxes need associating first");
  row.object = reader_.field(1);
  const double left = reader_.number(2), top = reader_.number(3);
  const double width = reader_.number(4), height = reader_.number(5);
  if (!(width > 0.0)) reader_.fail(4, "expected a width > 0, got " + reader_.field(4));
  if (!(height > 0.0)) reader_.fail(5, "expected a height > 0, got " + reader_.field(5));
  // The bottom centre: where a pedestrian stands, as the real-motion benchmark converts boxes.
  const Eigen::Vector3d foot(left + width / 2, top + height, 0.0);
  row.pose = make_pose(foot * kMetresPerPixel, Eigen::Quaterniond::Identity());
  return true;
}

bool LogRowReader::next(LogRow& row) {
  if (is_frame_numbered_format(format_)) {
    // A box file's rows that name no object it scores (KITTI's DontCare, gt.txt's ignored boxes)
    // are skipped.
    do {
      if (!reader_.next()) return false;
    } while (format_ == LogFormat::kKitti
                 ? !read_kitti_tracking_row(reader_, box_frame_period_, row)
                 : !read_mot_row(row));
    return true;
  }
  if (!reader_.next()) return false;
  row.line = reader_.line();
  row.t = reader_.number(column_[0]) * seconds_per_unit_;
  if (names_[1].empty()) {
    row.object = object_;
  } else {
    row.object = reader_.field(column_[1]);
    if (row.object.empty()) reader_.fail(column_[1], "expected an object name, got an empty field");
  }
  row.pose.reset();
  // A noise past kMaxNoise turns the estimates into NaN (core/option_schema.h), as in a setting.
  row.extra_noise = optional_length(extra_noise_column_, "a standard deviation", kMaxNoise);
  row.radius = optional_length(radius_column_, "a radius", std::numeric_limits<double>::max());
  row.box = read_box();

  const std::size_t fields = states_orientation_ ? kPoseFields : kPositionFields;
  std::size_t empty_fields = 0;
  for (std::size_t i = 0; i < fields; ++i)
    if (reader_.field(column_[2 + i]).empty()) ++empty_fields;
  if (empty_fields == fields) return true;  // explicitly unobserved
  if (empty_fields > 0) {
    for (std::size_t i = 0; i < fields; ++i)
      if (reader_.field(column_[2 + i]).empty())
        reader_.fail(column_[2 + i], states_orientation_
                                         ? "empty while other pose fields are set; leave all "
                                           "seven of x,y,z,qx,qy,qz,qw empty to mark the object "
                                           "unobserved"
                                         : "empty while other position fields are set; leave all "
                                           "three of x,y,z empty to mark the object unobserved");
  }

  std::array<double, kPoseFields> pose{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0};  // identity unless read
  for (std::size_t i = 0; i < fields; ++i) pose[i] = reader_.number(column_[2 + i]);
  const Eigen::Vector3d translation = Eigen::Vector3d(pose[0], pose[1], pose[2]) * metres_per_unit_;
  Eigen::Quaterniond orientation(pose[6], pose[3], pose[4], pose[5]);  // Eigen takes w first
  const double norm = orientation.norm();
  if (!(std::abs(norm - 1.0) <= kQuaternionNormTolerance)) {
    // Name the columns the fault spans; the line locates the row.
    throw InputError(reader_.source(), reader_.line(),
                     names_[5] + "," + names_[6] + "," + names_[7] + "," + names_[8],
                     "expected a unit quaternion (norm within " +
                         csv::format_double(kQuaternionNormTolerance) + " of 1), got norm " +
                         csv::format_double(norm));
  }
  orientation.normalize();
  row.pose = make_pose(translation, orientation);
  return true;
}

}  // namespace opf
