#include "opf/io/measurement_log_writer.h"

#include "opf/io/csv.h"

namespace opf {

void write_measurement_header(std::ostream& out) {
  out << "t,object,x,y,z,qx,qy,qz,qw\n";
}

void write_measurement_row(std::ostream& out, double t, const std::string& object,
                           const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation) {
  Eigen::Quaterniond q = orientation.normalized();
  if (q.w() < 0.0) q.coeffs() *= -1.0;
  out << csv::format_double(t) << ',' << csv::quote_if_needed(object);
  for (const double value : {position.x(), position.y(), position.z(), q.x(), q.y(), q.z(), q.w()})
    out << ',' << csv::format_double(value);
  out << '\n';
}

}  // namespace opf
