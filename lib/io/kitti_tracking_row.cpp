#include "opf/io/kitti_tracking_row.h"

#include "opf/core/pose_conversion.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <string>

namespace opf {
namespace {

// Field indices of kKittiColumns.
constexpr std::size_t kFrame = 0, kTrackId = 1, kHeight = 10, kWidth = 11, kLength = 12, kX = 13,
                      kRotationY = 16;

double whole_number(const csv::Reader& reader, std::size_t column, const char* what) {
  const double value = reader.number(column);
  if (value < 0.0 || value != std::floor(value))
    reader.fail(column, std::string("expected ") + what + " (0, 1, ...), got \"" +
                            reader.field(column) + "\"");
  return value;
}

}  // namespace

bool read_kitti_tracking_row(const csv::Reader& reader, double frame_period, LogRow& row) {
  if (reader.number(kTrackId) == -1.0) return false;  // DontCare
  const double frame = whole_number(reader, kFrame, "a frame number");
  const double id = whole_number(reader, kTrackId, "a track id, or -1 for DontCare");
  Eigen::Vector3d extents;  // length, height, width: along the box's own x, y, z
  const std::array<std::size_t, 3> columns = {kLength, kHeight, kWidth};
  for (Eigen::Index axis = 0; axis < 3; ++axis) {
    const std::size_t column = columns[static_cast<std::size_t>(axis)];
    extents[axis] = reader.number(column);
    if (!(extents[axis] > 0.0))
      reader.fail(column, "expected an extent > 0 (m), got " + reader.field(column));
  }
  const Eigen::Vector3d bottom(reader.number(kX), reader.number(kX + 1), reader.number(kX + 2));
  const double yaw = reader.number(kRotationY);
  row.line = reader.line();
  row.t = frame * frame_period;
  row.object = csv::format_double(id);  // "7" for 7 and 7.0 alike
  // y points down: the centre is half the height above the bottom.
  row.pose = make_pose(bottom - Eigen::Vector3d(0.0, extents[1] / 2.0, 0.0),
                       Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY())));
  row.box = extents;
  row.extra_noise = 0.0;
  row.radius = 0.0;
  return true;
}

}  // namespace opf
