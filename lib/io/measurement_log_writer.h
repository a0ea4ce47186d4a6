#pragma once
// Writes measurement logs (the format of measurement_log.h) so that read_measurement_log gives the
// same numbers back: the shortest exact text for every number, the quaternion with qw >= 0.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <ostream>
#include <string>

namespace opf {

/// The header line "t,object,x,y,z,qx,qy,qz,qw".
void write_measurement_header(std::ostream& out);

/// One detection; `orientation` is normalised and written with qw >= 0. The object name is quoted
/// when it needs to be (commas, quotes, surrounding spaces).
void write_measurement_row(std::ostream& out, double t, const std::string& object,
                           const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation);

}  // namespace opf
