// The likelihood kernels: the exponents of Eq. 5 per particle.

#include "opf/particles/likelihood_kernels.h"

#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "particles/quaternion_clouds.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace opf {
namespace {

using test::cloud_of_spread;
using test::column;

// Float quaternions resolve angles to a few 1e-8 rad; the product z^-1 q adds about four
// roundings of 6e-8 per component, so the kernel's angle is good to 5e-7 rad (the worst seen over
// these clouds is 4e-7 near pi and 1.2e-7 below 60 degrees). The exponent s theta^2 then moves
// by at most |s| (2 theta + delta) delta.
double exponent_tolerance(double scale, double angle) {
  constexpr double kAngleResolution = 5e-7;
  return std::abs(scale) * (2.0 * angle + kAngleResolution) * kAngleResolution;
}

TEST(LikelihoodKernels, RotationExponentsAreMinusHalfSquaredAnglesOverVariance) {
  Random random(4);
  const std::size_t n = 1001;  // three whole blocks and a partial one
  const Eigen::Quaterniond z = so3::exp(Eigen::Vector3d(1.0, 0.5, -2.0));
  for (const double spread : {0.05, 0.3, 1.5, -1.0}) {
    const std::vector<float> q = cloud_of_spread(n, z, spread, random);
    const double variance = 0.0025, scale = -0.5 / variance;
    std::vector<double> out(n, 1.0);
    const double best = kernels::rotation_exponents(q.data(), n, {z.x(), z.y(), z.z(), z.w()},
                                                    scale, out.data(), true);
    double expected_best = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      const double angle = so3::angle_between(column(q, n, i), z);
      const double expected = scale * angle * angle;
      expected_best = std::max(expected_best, expected);
      EXPECT_NEAR(out[i], 1.0 + expected, exponent_tolerance(scale, angle))
          << "spread " << spread << ", particle " << i;
    }
    EXPECT_NEAR(best, expected_best, exponent_tolerance(scale, std::sqrt(expected_best / scale)));
  }
}

TEST(LikelihoodKernels, TranslationExponentsOverwriteOrAccumulate) {
  const std::size_t n = 9;
  std::vector<double> x(3 * n);
  for (std::size_t i = 0; i < 3 * n; ++i) x[i] = 0.1 * static_cast<double>(i);
  std::vector<double> out(n, 5.0);
  const std::array<double, 3> z{0.2, 1.1, 2.0};
  const double best = kernels::translation_exponents(x.data(), n, z, -2.0, out.data(), false);
  double expected_best = -1e300;
  for (std::size_t i = 0; i < n; ++i) {
    const double d2 =
        std::pow(x[i] - z[0], 2) + std::pow(x[n + i] - z[1], 2) + std::pow(x[2 * n + i] - z[2], 2);
    EXPECT_NEAR(out[i], -2.0 * d2, 1e-14);
    expected_best = std::max(expected_best, -2.0 * d2);
  }
  EXPECT_DOUBLE_EQ(best, expected_best);
  const std::vector<double> first = out;
  kernels::translation_exponents(x.data(), n, z, -2.0, out.data(), true);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(out[i], 2.0 * first[i], 1e-14);
}

// A scale per axis (a diagonal Q): each squared difference by its own axis's scale.
TEST(LikelihoodKernels, TranslationExponentsWithAScalePerAxis) {
  const std::size_t n = 1001;  // three whole blocks and a partial one
  Random random(5);
  std::vector<double> x(3 * n);
  for (double& v : x) v = 0.05 * random.normal();
  std::vector<double> out(n, 5.0);
  const std::array<double, 3> z{0.01, -0.02, 0.03}, scale{-2.0, -50.0, -0.5};
  const double best = kernels::translation_exponents(x.data(), n, z, scale, out.data(), true);
  double expected_best = -1e300;
  for (std::size_t i = 0; i < n; ++i) {
    double expected = 0.0;
    for (std::size_t a = 0; a < 3; ++a) expected += scale[a] * std::pow(x[a * n + i] - z[a], 2);
    EXPECT_NEAR(out[i], 5.0 + expected, 1e-13) << i;
    expected_best = std::max(expected_best, expected);
  }
  EXPECT_NEAR(best, expected_best, 1e-15);
}

}  // namespace
}  // namespace opf
