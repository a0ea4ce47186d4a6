// The motion kernels: tangent random walks and turns of quaternion particles.

#include "opf/particles/motion_kernels.h"

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

using test::column;
using test::quaternion_rows;

// Steps of every length: up to ~6 rad in every block (sin and cos by reduction), up to ~0.6 rad
// (the polynomials in |e|^2), the same with one shared sigma, and short steps with one long one
// in the second block.
TEST(MotionKernels, PerturbQuaternionsIsTheTangentRandomWalk) {
  Random random(2);
  const std::size_t n = 1003;  // not a multiple of any vector width
  const Eigen::Quaterniond centre = so3::exp(Eigen::Vector3d(0.3, -1.2, 2.0));
  enum class Steps { kLong, kShort, kShared, kOneLong };
  for (const Steps steps : {Steps::kLong, Steps::kShort, Steps::kShared, Steps::kOneLong}) {
    std::vector<float> q = quaternion_rows(n, centre, 0.3, random);
    const std::vector<float> before = q;
    std::vector<float> noise(3 * n);
    for (float& v : noise) v = static_cast<float>(3.0 * random.normal());  // up to ~12 sigma
    std::vector<double> sigma(n);
    const double largest = steps == Steps::kLong ? 0.5 : 0.05;
    for (double& s : sigma) s = steps == Steps::kShared ? largest : largest * random.uniform();
    if (steps == Steps::kOneLong) sigma[300] = 1.0;
    kernels::perturb_quaternions(q.data(), n, n, noise.data(), largest,
                                 steps == Steps::kShared ? nullptr : sigma.data());
    double worst_angle = 0.0, worst_norm = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d step =
          sigma[i] * Eigen::Vector3d(noise[i], noise[n + i], noise[2 * n + i]);
      const Eigen::Quaterniond expected = column(before, n, i) * so3::exp(step);
      worst_angle = std::max(worst_angle, so3::angle_between(column(q, n, i), expected));
      worst_norm = std::max(worst_norm, std::abs(column(q, n, i).norm() - 1.0));
    }
    // Single precision: a few float epsilons (1.2e-7) of angle and of norm.
    EXPECT_LT(worst_angle, 1e-6) << static_cast<int>(steps);
    EXPECT_LT(worst_norm, 5e-7) << static_cast<int>(steps);
  }
}

TEST(MotionKernels, RotateQuaternionsTurnsEveryParticle) {
  Random random(3);
  const std::size_t n = 77;
  std::vector<float> q = quaternion_rows(n, Eigen::Quaterniond::Identity(), 1.0, random);
  const std::vector<float> before = q;
  const Eigen::Quaterniond turn = so3::exp(Eigen::Vector3d(0.1, 0.7, -0.4));
  kernels::rotate_quaternions(q.data(), n, {turn.x(), turn.y(), turn.z(), turn.w()});
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_LT(so3::angle_between(column(q, n, i), turn * column(before, n, i)), 1e-6);
}

// The velocity drift's fused step does in one pass exactly what a turn and then the random walk
// do in two, bit for bit: the OPF's results do not depend on which path ran.
TEST(MotionKernels, TurnAndPerturbIsTheTurnThenTheRandomWalk) {
  Random random(4);
  const std::size_t n = 1003;
  for (const double sigma : {0.02, 2.0}) {  // the polynomial path and the reduction's
    std::vector<float> fused =
        quaternion_rows(n, so3::exp(Eigen::Vector3d(0.2, 0.1, -0.3)), 0.2, random);
    std::vector<float> two_passes = fused;
    std::vector<float> noise(3 * n);
    for (float& v : noise) v = static_cast<float>(random.normal());
    const Eigen::Quaterniond turn = so3::exp(Eigen::Vector3d(0.05, -0.02, 0.3));
    const std::array<double, 4> r{turn.x(), turn.y(), turn.z(), turn.w()};
    kernels::turn_and_perturb_quaternions(fused.data(), n, n, noise.data(), sigma, r);
    kernels::rotate_quaternions(two_passes.data(), n, r);
    kernels::perturb_quaternions(two_passes.data(), n, n, noise.data(), sigma, nullptr);
    EXPECT_EQ(fused, two_passes) << sigma;
  }
  std::vector<double> x(1003), shifted(1003);
  std::vector<float> noise(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = shifted[i] = random.normal();
    noise[i] = static_cast<float>(random.normal());
  }
  kernels::add_offset_and_scaled_noise(x.data(), noise.data(), 0.25, 0.01, x.size());
  for (double& v : shifted) v += 0.25;
  kernels::add_scaled_noise(shifted.data(), noise.data(), 0.01, shifted.size());
  EXPECT_EQ(x, shifted);
}

}  // namespace
}  // namespace opf
