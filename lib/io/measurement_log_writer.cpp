#include "opf/io/measurement_log_writer.h"

#include "opf/core/pose_conversion.h"
#include "opf/io/csv.h"
#include "opf/io/log_read_options.h"

namespace opf {
namespace {

void write_pose(std::ostream& out, double t, const std::string& object,
                const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation) {
  Eigen::Quaterniond q = orientation.normalized();
  if (q.w() < 0.0) q.coeffs() *= -1.0;
  out << csv::format_time(t) << ',' << csv::quote_if_needed(object);
  for (const double value : {position.x(), position.y(), position.z(), q.x(), q.y(), q.z(), q.w()})
    out << ',' << csv::format_double(value);
}

// A stated value, or an empty field for none (0).
void write_stated(std::ostream& out, double value) {
  out << ',';
  if (value != 0.0) out << csv::format_double(value);
}

}  // namespace

StatedColumns stated_columns(std::span<const Frame> frames) {
  StatedColumns columns;
  for (const Frame& frame : frames)
    for (const Detection& d : frame.detections) {
      columns.extra_noise = columns.extra_noise || d.extra_noise != 0.0;
      columns.radius = columns.radius || d.radius != 0.0;
      columns.box = columns.box || !d.box.isZero();
    }
  return columns;
}

void write_measurement_header(std::ostream& out, StatedColumns columns) {
  out << "t,object,x,y,z,qx,qy,qz,qw";
  if (columns.extra_noise) out << ',' << kExtraNoiseColumn;
  if (columns.radius) out << ',' << kRadiusColumn;
  if (columns.box)
    for (const std::string_view name : kBoxColumns) out << ',' << name;
  out << '\n';
}

void write_measurement_row(std::ostream& out, double t, const std::string& object,
                           const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation) {
  write_pose(out, t, object, position, orientation);
  out << '\n';
}

void write_measurement_rows(std::ostream& out, std::span<const Frame> frames,
                            StatedColumns columns) {
  for (const Frame& frame : frames)
    for (const Detection& d : frame.detections) {
      write_pose(out, frame.t, d.object, translation_of(d.pose), orientation_of(d.pose));
      if (columns.extra_noise) write_stated(out, d.extra_noise);
      if (columns.radius) write_stated(out, d.radius);
      if (columns.box && d.box.isZero()) out << ",,,";
      if (columns.box && !d.box.isZero())  // all three, as the reader wants them
        for (const double extent : {d.box.x(), d.box.y(), d.box.z()})
          out << ',' << csv::format_double(extent);
      out << '\n';
    }
}

}  // namespace opf
