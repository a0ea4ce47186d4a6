#pragma once
// Rotation-group helpers on unit quaternions. Perturbations live in the tangent space on the
// right: q' = q * exp(delta), delta a rotation vector in the body frame.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace opf::so3 {

/// Unit quaternion of the rotation vector `v` (angle |v| about v/|v|), accurate near zero.
Eigen::Quaterniond exp(const Eigen::Vector3d& v);

/// Rotation vector of `q` with angle in [0, pi]; q and -q give the same result.
Eigen::Vector3d log(const Eigen::Quaterniond& q);

/// Geodesic angle in [0, pi] between two orientations: 2 atan2(|v|, |w|) of a^-1 b, which stays
/// accurate near 0 and pi where acos of a clamped dot product does not.
double angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

/// Body-frame rotation vector taking `from` to `to`: log(from^-1 to).
Eigen::Vector3d difference(const Eigen::Quaterniond& from, const Eigen::Quaterniond& to);

}  // namespace opf::so3
