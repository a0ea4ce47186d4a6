#pragma once
// One detection row of a measurement log at a time, in the toolkit's units (seconds, metres), with
// the file's own column names mapped to the format's: the first stage of reading a log, shared by
// whole-file reading and streams.

#include "opf/io/csv.h"
#include "opf/io/log_read_options.h"

#include <mrpt/poses/CPose3D.h>
#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <string_view>

namespace opf {

struct LogRow {
  double t = 0.0;  ///< seconds
  std::string object;
  /// Empty when all its pose fields are: the object is unobserved at t.
  std::optional<mrpt::poses::CPose3D> pose;
  /// m: the extra noise the detector states for the detection (column kExtraNoiseColumn, scaled
  /// by the length unit; empty: 0), Detection::extra_noise.
  double extra_noise = 0.0;
  /// m: the object's extent the detector states (column kRadiusColumn, scaled by the length unit;
  /// empty: 0), Detection::radius.
  double radius = 0.0;
  /// m: the object's bounding box the detector states (columns kBoxColumns, scaled by the length
  /// unit; all three empty: zero), Detection::box.
  Eigen::Vector3d box = Eigen::Vector3d::Zero();
  std::size_t line = 0;  ///< 1-based line in the file, for error messages
};

/// What a program says of a log of positions alone (LogRowReader::states_orientation): one
/// sentence, without a trailing full stop.
std::string positions_only_note();

class LogRowReader {
 public:
  /// Reads the header (a TUM file has none); throws InputError when a (mapped) column is missing.
  /// A log without an object column (TUM, or a CSV with `options.object`) gives every row
  /// `options.object`.
  LogRowReader(std::istream& in, const std::string& source, const LogReadOptions& options);

  /// The next row, false at the end of input. Throws InputError naming the file, line and column
  /// of a malformed row.
  bool next(LogRow& row);

  const std::string& source() const { return reader_.source(); }
  /// False for a CSV log of positions alone (no qx, qy, qz, qw column): every row's orientation
  /// is the identity, as a MOTChallenge box's is.
  bool states_orientation() const { return states_orientation_; }

 private:
  /// The current row of a MOTChallenge file into `row`; false for a box gt.txt flags as ignored.
  bool read_mot_row(LogRow& row) const;
  /// The current row's optional length `column` (0 without the column or where empty), checked
  /// from 0 to `max_metres` (`what` names the quantity in the error), in metres.
  double optional_length(const std::optional<std::size_t>& column, std::string_view what,
                         double max_metres) const;

  LogFormat format_;
  std::array<std::string, 9> names_;  // the file's names of t, object, x, y, z, qx, qy, qz, qw
  csv::Reader reader_;
  std::string object_;             // every row's object when the file has no object column
  double box_frame_period_ = 0.0;  // s per frame number: a MOTChallenge or KITTI file
  std::array<std::size_t, 9> column_{};
  std::optional<std::size_t> extra_noise_column_;          // a CSV log's optional kExtraNoiseColumn
  std::optional<std::size_t> radius_column_;               // a CSV log's optional kRadiusColumn
  std::array<std::optional<std::size_t>, 3> box_columns_;  // a CSV log's optional kBoxColumns
  Eigen::Vector3d read_box() const;
  double seconds_per_unit_ = 1.0;
  double metres_per_unit_ = 1.0;
  bool states_orientation_ = true;
};

}  // namespace opf
