// The statistics kernels: moment sums against direct sums.

#include "opf/particles/statistics_kernels.h"

#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "particles/quaternion_clouds.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <vector>

namespace opf {
namespace {

using test::cloud_of_spread;
using test::column;
using test::quaternion_rows;

// The tangent second moment about the mean against so3::log in double, for every kind of block.
TEST(StatisticsKernels, TangentSecondMomentIsTheSumOfLogOuterProducts) {
  Random random(8);
  const std::size_t n = 1001;
  const Eigen::Quaterniond mean = so3::exp(Eigen::Vector3d(-0.4, 1.1, 0.3));
  for (const double spread : {0.05, 0.3, 1.0, -1.0}) {
    const std::vector<float> q = cloud_of_spread(n, mean, spread, random);
    std::vector<double> w(n);
    for (double& v : w) v = random.uniform();
    for (const bool weighted : {false, true}) {
      const std::array<double, 6> t = kernels::tangent_second_moment(
          q.data(), n, weighted ? w.data() : nullptr, {-mean.x(), -mean.y(), -mean.z(), mean.w()});
      std::array<double, 6> expected{};
      for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d d = so3::log(mean.conjugate() * column(q, n, i));
        const double wi = weighted ? w[i] : 1.0;
        const std::array<double, 6> terms{d.x() * d.x(), d.x() * d.y(), d.x() * d.z(),
                                          d.y() * d.y(), d.y() * d.z(), d.z() * d.z()};
        for (std::size_t k = 0; k < 6; ++k) expected[k] += wi * terms[k];
      }
      // Single precision tangent vectors: 1e-6 relative to the largest diagonal term.
      const double tolerance = 1e-6 * std::max({expected[0], expected[3], expected[5]});
      for (std::size_t k = 0; k < 6; ++k)
        EXPECT_NEAR(t[k], expected[k], tolerance)
            << "spread " << spread << ", weighted " << weighted << ", term " << k;
    }
  }
}

TEST(StatisticsKernels, MomentSumsMatchDirectSums) {
  Random random(5);
  const std::size_t n = 513;
  std::vector<double> x(3 * n), w(n);
  for (double& v : x) v = 1000.0 + random.normal();  // far from the origin
  for (double& v : w) v = random.uniform();
  const std::array<double, 3> ref{x[0], x[n], x[2 * n]};
  const kernels::TranslationSums s = kernels::translation_sums(x.data(), n, w.data(), ref);
  double sw = 0, sx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sw += w[i];
    sx += w[i] * (x[i] - ref[0]);
    sxy += w[i] * (x[i] - ref[0]) * (x[n + i] - ref[1]);
  }
  EXPECT_NEAR(s.weight, sw, 1e-12);
  EXPECT_NEAR(s.first[0], sx, 1e-11);
  EXPECT_NEAR(s.second[1], sxy, 1e-11);

  const Eigen::Quaterniond mean = so3::exp(Eigen::Vector3d(0.2, 0.1, -0.5));
  const std::vector<float> q = quaternion_rows(n, mean, 0.2, random);
  const std::array<double, 10> m = kernels::quaternion_second_moment(q.data(), n, w.data());
  const std::array<double, 6> t = kernels::tangent_second_moment(
      q.data(), n, nullptr, {-mean.x(), -mean.y(), -mean.z(), mean.w()});
  double mxw = 0, tzz = 0, txy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Quaterniond qi = column(q, n, i);
    mxw += w[i] * qi.x() * qi.w();
    const Eigen::Vector3d d = so3::log(mean.conjugate() * qi);
    tzz += d.z() * d.z();
    txy += d.x() * d.y();
  }
  EXPECT_NEAR(m[3], mxw, 1e-12);
  // Single precision tangent vectors: 1e-6 relative.
  EXPECT_NEAR(t[5], tzz, 1e-6 * tzz);
  EXPECT_NEAR(t[1], txy, 1e-6 * tzz);
}

}  // namespace
}  // namespace opf
