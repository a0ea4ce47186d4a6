#include "opf/core/so3.h"

#include <cmath>

namespace opf::so3 {

namespace {

// Below these, the Taylor series of sin and cos of the half angle and of atan(u) / u: every term
// left out is under 1e-19 relative, and the polynomials cost a fraction of libm's sin, cos and
// atan2 (a motion-model bank's members turn by milliradians a frame).
constexpr double kSeriesHalfAngle = 0.05;  // rad
constexpr double kSeriesTangent = 0.05;    // |v| / w of the quaternion, tan of the half angle

}  // namespace

Eigen::Quaterniond exp(const Eigen::Vector3d& v) {
  const double z = 0.25 * v.squaredNorm();  // the half angle h, squared
  if (z < kSeriesHalfAngle * kSeriesHalfAngle) {
    // sin(h) / h = 1 - z/6 + z^2/120 - ..., cos h = 1 - z/2 + z^2/24 - ... (to z^5 and z^6)
    const double sin_over =
        1.0 - z / 6.0 * (1.0 - z / 20.0 * (1.0 - z / 42.0 * (1.0 - z / 72.0 * (1.0 - z / 110.0))));
    const double cos_half =
        1.0 -
        z / 2.0 *
            (1.0 -
             z / 12.0 * (1.0 - z / 30.0 * (1.0 - z / 56.0 * (1.0 - z / 90.0 * (1.0 - z / 132.0)))));
    const double k = 0.5 * sin_over;  // sin(h) / |v|
    return Eigen::Quaterniond(cos_half, k * v.x(), k * v.y(), k * v.z());
  }
  const double angle = std::sqrt(4.0 * z);
  const double k = std::sin(0.5 * angle) / angle;
  return Eigen::Quaterniond(std::cos(0.5 * angle), k * v.x(), k * v.y(), k * v.z());
}

Eigen::Vector3d log(const Eigen::Quaterniond& q_in) {
  // Pick the hemisphere with w >= 0 so the angle is the shorter one, in [0, pi].
  const Eigen::Quaterniond q = q_in.w() < 0.0 ? Eigen::Quaterniond(-q_in.coeffs()) : q_in;
  const double square = q.vec().squaredNorm();
  if (square < kSeriesTangent * kSeriesTangent * q.w() * q.w()) {
    // angle / s = 2 atan(u) / (u w), u = s / w: atan(u) / u = 1 - z/3 + z^2/5 - ... to z^6
    const double z = square / (q.w() * q.w());
    const double atan_over =
        1.0 - z * (1.0 / 3.0 -
                   z * (1.0 / 5.0 -
                        z * (1.0 / 7.0 - z * (1.0 / 9.0 - z * (1.0 / 11.0 - z * (1.0 / 13.0))))));
    return q.vec() * (2.0 * atan_over / q.w());
  }
  const double s = std::sqrt(square);
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
