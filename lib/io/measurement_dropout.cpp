#include "opf/io/measurement_dropout.h"

#include "opf/io/csv.h"
#include "opf/io/input_error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string_view>

namespace opf {

namespace {

constexpr std::array<std::string_view, 5> kRequiredColumns = {"t", "object", "x", "y", "z"};

void write_fields(std::ostream& out, const std::vector<std::string>& fields) {
  for (std::size_t i = 0; i < fields.size(); ++i)
    out << (i ? "," : "") << csv::quote_if_needed(fields[i]);
  out << '\n';
}

}  // namespace

void check_dropout_windows(const DropoutWindows& windows) {
  if (!std::isfinite(windows.start))
    throw std::invalid_argument("dropout: the first window's start must be a finite time");
  if (!(windows.period > 0.0) || !std::isfinite(windows.period))
    throw std::invalid_argument("dropout: the period must be a positive number of seconds");
  if (!(windows.length > 0.0) || !(windows.length < windows.period))
    throw std::invalid_argument(
        "dropout: the window length must be > 0 and shorter than the period");
}

bool in_dropout_window(double t, const DropoutWindows& windows) {
  if (t - windows.start < -kDropoutTimeTolerance) return false;
  // Measured from the start's own phase (std::fmod is exact): a start far from t, say -1e300 s,
  // would otherwise leave t - start no digits of t.
  const double since = t - std::fmod(windows.start, windows.period);
  const double k = std::floor((since + kDropoutTimeTolerance) / windows.period);
  const double phase = since - k * windows.period;  // in [-tolerance, period)
  return phase < windows.length - kDropoutTimeTolerance;
}

DropoutCounts apply_dropout(std::istream& in, const std::string& source, std::ostream& out,
                            const std::vector<std::string>& objects,
                            const DropoutWindows& windows) {
  check_dropout_windows(windows);
  // The quaternion's columns all or none, as the tracker reads a log (a log of positions: none).
  const csv::ColumnGroup quaternion{{"qx", "qy", "qz", "qw"}};
  csv::Reader reader(in, source, kRequiredColumns, quaternion);
  const std::size_t t_column = reader.column("t");
  const std::size_t object_column = reader.column("object");
  std::vector<std::size_t> pose_columns;
  for (std::size_t i = 2; i < kRequiredColumns.size(); ++i)
    pose_columns.push_back(reader.column(kRequiredColumns[i]));
  if (reader.has_column(quaternion.names.front()))
    for (const std::string& name : quaternion.names) pose_columns.push_back(reader.column(name));

  write_fields(out, reader.header());
  std::vector<bool> seen(objects.size(), false);
  DropoutCounts counts;
  while (reader.next()) {
    std::vector<std::string> fields(reader.header().size());
    for (std::size_t i = 0; i < fields.size(); ++i) fields[i] = reader.field(i);
    const double t = reader.number(t_column);
    const std::string& object = fields[object_column];
    bool chosen = objects.empty();
    for (std::size_t i = 0; i < objects.size(); ++i)
      if (objects[i] == object) chosen = seen[i] = true;  // an object named twice, each time
    if (chosen && in_dropout_window(t, windows)) {
      bool had_pose = false;
      for (const std::size_t column : pose_columns) {
        had_pose = had_pose || !fields[column].empty();
        fields[column].clear();
      }
      counts.blanked += had_pose ? 1 : 0;
    }
    write_fields(out, fields);
    ++counts.rows;
  }
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (!seen[i])
      throw InputError(source, 0, "object", "no row of object '" + objects[i] + "' to drop");
  return counts;
}

}  // namespace opf
