#include "opf/io/estimate_tum.h"

#include "opf/core/pose_conversion.h"
#include "opf/io/csv.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace opf {

void write_tum_header(std::ostream& out) {
  out << "# timestamp tx ty tz qx qy qz qw\n";
}

void write_tum_row(std::ostream& out, const Estimate& estimate) {
  const Eigen::Vector3d p = translation_of(estimate.pose.mean);
  Eigen::Quaterniond q = orientation_of(estimate.pose.mean);
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  out << csv::format_time(estimate.t);
  for (const double v : {p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w()})
    out << ' ' << csv::format_double(v);
  out << '\n';
}

std::vector<std::filesystem::path> tum_paths(const std::filesystem::path& out,
                                             const std::vector<std::string>& objects) {
  if (objects.size() == 1) return {out};
  std::vector<std::filesystem::path> paths;
  for (std::string object : objects) {
    std::replace(object.begin(), object.end(), '/', '_');
    paths.push_back(out.parent_path() /
                    (out.stem().string() + "_" + object + out.extension().string()));
  }
  return paths;
}

}  // namespace opf
