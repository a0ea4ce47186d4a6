#include "io/measurement_log.h"

#include "core/pose_conversion.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "io/input_file.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <utility>

namespace opf {

namespace {

constexpr std::array<std::string_view, 9> kColumns = {"t",  "object", "x",  "y", "z",
                                                      "qx", "qy",     "qz", "qw"};
constexpr std::size_t kPoseFields = 7;  // x, y, z, qx, qy, qz, qw: kColumns[2..8]
constexpr double kQuaternionNormTolerance = 0.01;

}  // namespace

MeasurementLog parse_measurement_log(std::istream& in, const std::string& source_name) {
  csv::Reader reader(in, source_name, kColumns);
  std::array<std::size_t, kColumns.size()> column{};
  for (std::size_t i = 0; i < kColumns.size(); ++i) column[i] = reader.column(kColumns[i]);
  const std::size_t t_column = column[0];
  const std::size_t object_column = column[1];

  std::map<double, Frame> frames;
  // Line of each (t, object) row seen, to reject and point back at duplicates.
  std::map<std::pair<double, std::string>, std::size_t> row_lines;
  while (reader.next()) {
    const double t = reader.number(t_column);
    const std::string& object = reader.field(object_column);
    if (object.empty()) reader.fail(object_column, "expected an object name, got an empty field");

    const auto [seen, inserted] = row_lines.emplace(std::pair(t, object), reader.line());
    if (!inserted)
      reader.fail(object_column, "object '" + object +
                                     "' appears twice at t = " + csv::format_double(t) +
                                     " (first on line " + std::to_string(seen->second) + ")");
    Frame& frame = frames[t];
    frame.t = t;

    std::size_t empty_fields = 0;
    for (std::size_t i = 0; i < kPoseFields; ++i)
      if (reader.field(column[2 + i]).empty()) ++empty_fields;
    if (empty_fields == kPoseFields) continue;  // explicitly unobserved
    if (empty_fields > 0) {
      for (std::size_t i = 0; i < kPoseFields; ++i)
        if (reader.field(column[2 + i]).empty())
          reader.fail(column[2 + i],
                      "empty while other pose fields are set; leave all seven of x,y,z,qx,qy,qz,qw "
                      "empty to mark the object unobserved");
    }

    std::array<double, kPoseFields> pose{};
    for (std::size_t i = 0; i < kPoseFields; ++i) pose[i] = reader.number(column[2 + i]);
    const Eigen::Vector3d translation(pose[0], pose[1], pose[2]);
    Eigen::Quaterniond orientation(pose[6], pose[3], pose[4], pose[5]);  // Eigen takes w first
    const double norm = orientation.norm();
    if (!(std::abs(norm - 1.0) <= kQuaternionNormTolerance)) {
      // Name the columns the fault spans; the line locates the row.
      throw InputError(source_name, reader.line(), "qx,qy,qz,qw",
                       "expected a unit quaternion (norm within " +
                           csv::format_double(kQuaternionNormTolerance) + " of 1), got norm " +
                           csv::format_double(norm));
    }
    orientation.normalize();
    frame.detections.push_back({object, make_pose(translation, orientation)});
  }

  MeasurementLog log;
  if (std::none_of(frames.begin(), frames.end(),
                   [](const auto& entry) { return !entry.second.detections.empty(); }))
    throw InputError(source_name, 0, "",
                     "no detections: the log has no row with a pose (a header only, or every "
                     "object unobserved), so there is nothing to track or compare");
  log.frames.reserve(frames.size());
  for (auto& [t, frame] : frames) {
    for (const auto& detection : frame.detections)
      if (std::find(log.objects.begin(), log.objects.end(), detection.object) == log.objects.end())
        log.objects.push_back(detection.object);
    log.frames.push_back(std::move(frame));
  }
  return log;
}

MeasurementLog read_measurement_log(const std::filesystem::path& path) {
  std::ifstream in = open_input_file(path, "measurement log");
  return parse_measurement_log(in, path.string());
}

}  // namespace opf
