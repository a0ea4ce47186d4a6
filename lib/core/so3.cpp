#include "opf/core/so3.h"

#include <cmath>

namespace opf::so3 {

Eigen::Quaterniond exp(const Eigen::Vector3d& v) {
  const double angle = v.norm();
  const double half = 0.5 * angle;
  // sin(a/2)/a by its Taylor series below 1e-4 rad, where the division loses precision.
  const double k = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(half) / angle;
  return Eigen::Quaterniond(std::cos(half), k * v.x(), k * v.y(), k * v.z());
}

Eigen::Vector3d log(const Eigen::Quaterniond& q_in) {
  // Pick the hemisphere with w >= 0 so the angle is the shorter one, in [0, pi].
  const Eigen::Quaterniond q = q_in.w() < 0.0 ? Eigen::Quaterniond(-q_in.coeffs()) : q_in;
  const double s = q.vec().norm();
  if (s < 1e-12) return 2.0 * q.vec() / q.w();  // first order; w ~ 1 here
  const double angle = 2.0 * std::atan2(s, q.w());
  return q.vec() * (angle / s);
}

double angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const Eigen::Quaterniond d = a.conjugate() * b;
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

Eigen::Vector3d difference(const Eigen::Quaterniond& from, const Eigen::Quaterniond& to) {
  return log(from.conjugate() * to);
}

}  // namespace opf::so3
