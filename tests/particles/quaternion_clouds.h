#pragma once
// Test clouds of rotation particles in the kernels' layout (four rows x, y, z, w of floats).

#include "opf/core/random.h"
#include "opf/core/so3.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace opf::test {

// Random unit quaternions near `centre` with `spread` rad of tangent noise, as four rows.
inline std::vector<float> quaternion_rows(std::size_t n, const Eigen::Quaterniond& centre,
                                          double spread, Random& random) {
  std::vector<float> q(4 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d e(random.normal(), random.normal(), random.normal());
    const Eigen::Quaterniond v = centre * so3::exp(spread * e);
    for (int r = 0; r < 4; ++r) q[r * n + i] = static_cast<float>(v.coeffs()[r]);
  }
  return q;
}

inline Eigen::Quaterniond column(const std::vector<float>& q, std::size_t n, std::size_t i) {
  return Eigen::Quaterniond(q[3 * n + i], q[i], q[n + i], q[2 * n + i]);
}

// Clouds of every spread: 0.05 rad keeps every block of particles within 60 degrees of z (the
// kernel's asin polynomial), 1.5 rad puts far particles in every block (the arctangent over its
// whole range), 0.3 rad mixes the two; one far particle among near ones sends only its block
// down the arctangent path.
inline std::vector<float> cloud_of_spread(std::size_t n, const Eigen::Quaterniond& centre,
                                          double spread, Random& random) {
  std::vector<float> q = quaternion_rows(n, centre, spread > 0.0 ? spread : 0.05, random);
  if (spread < 0.0) {  // one stray particle, 2.5 rad away, in the second block
    const Eigen::Quaterniond far = centre * so3::exp(Eigen::Vector3d(0.0, 2.5, 0.0));
    for (int r = 0; r < 4; ++r) q[r * n + 300] = static_cast<float>(far.coeffs()[r]);
  }
  return q;
}

}  // namespace opf::test
