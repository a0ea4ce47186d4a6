#pragma once
// Writes measurement logs (the format of measurement_log.h) so that read_measurement_log gives the
// same numbers back: the shortest exact text for every number, the quaternion with qw >= 0.

#include "opf/core/frame.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <ostream>
#include <span>
#include <string>

namespace opf {

/// The optional columns a log has: what its detections state beyond the pose (frame.h).
struct StatedColumns {
  bool extra_noise = false;
  bool radius = false;
  bool box = false;  ///< box_x, box_y, box_z
};

/// The columns that some detection of `frames` states (a nonzero value).
StatedColumns stated_columns(std::span<const Frame> frames);

/// The header line "t,object,x,y,z,qx,qy,qz,qw", then the stated columns'.
void write_measurement_header(std::ostream& out, StatedColumns columns = {});

/// One detection; `orientation` is normalised and written with qw >= 0. The object name is quoted
/// when it needs to be (commas, quotes, surrounding spaces).
void write_measurement_row(std::ostream& out, double t, const std::string& object,
                           const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation);

/// Every detection of `frames`, in order, with the columns of `columns` (written empty where a
/// detection states none: 0).
void write_measurement_rows(std::ostream& out, std::span<const Frame> frames,
                            StatedColumns columns);

}  // namespace opf
