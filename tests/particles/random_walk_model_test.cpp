// The multiple-model steps of random_walk_model.h: each particle moved by its own model's entry.

#include "opf/particles/random_walk_model.h"

#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

constexpr std::size_t kCount = 20000;

// Members alternate 0, 1: model 0 shifts by +0.1 m with no spread, model 1 by -0.2 m with a
// 0.01 m spread. Model 0's particles land exactly; model 1's mean and spread are within 4 sigma of
// their sampling error over 10000 particles (0.4e-3 m and 3%).
TEST(RandomWalkModel, EachRowParticleMovesByItsOwnMember) {
  TranslationParticles particles;
  particles.resize(kCount);
  particles.states.setZero();
  std::vector<std::uint8_t> members(kCount);
  for (std::size_t i = 0; i < kCount; ++i) members[i] = static_cast<std::uint8_t>(i % 2);
  const std::vector<double> offset{0.1, -0.2}, spread{0.0, 0.01};
  GaussianSampler noise(3);
  predict_row_by_member(particles, 1, members, offset, spread, noise);
  double sum = 0.0, squares = 0.0;
  for (std::size_t i = 0; i < kCount; ++i) {
    const auto c = static_cast<Eigen::Index>(i);
    EXPECT_EQ(particles.states(0, c), 0.0);  // the other rows untouched
    EXPECT_EQ(particles.states(2, c), 0.0);
    if (members[i] == 0) {
      EXPECT_DOUBLE_EQ(particles.states(1, c), 0.1);
    } else {
      sum += particles.states(1, c);
      squares += particles.states(1, c) * particles.states(1, c);
    }
  }
  const double n = kCount / 2.0, mean = sum / n;
  EXPECT_NEAR(mean, -0.2, 4e-4);
  EXPECT_NEAR(std::sqrt(squares / n - mean * mean), 0.01, 3e-4);
  EXPECT_THROW(predict_row_by_member(particles, 3, members, offset, spread, noise),
               std::invalid_argument);
  EXPECT_THROW(predict_row_by_member(particles, 0, members, offset, {spread.data(), 1}, noise),
               std::invalid_argument);
}

// Two segments: the first half turned by a quarter turn about z with no spread (exactly, to float
// precision), the second held and spread by 0.05 rad per tangent axis: the rms angle from the
// start is 0.05 sqrt(3) within 3%.
TEST(RandomWalkModel, EachSegmentTurnsAndSpreadsByItsOwnModel) {
  RotationParticles particles;
  particles.resize(kCount);
  const Eigen::Quaterniond start = so3::exp(Eigen::Vector3d(0.3, -0.2, 0.1));
  particles.states.colwise() = start.coeffs().cast<float>();
  const std::vector<std::size_t> ends{kCount / 2, kCount};
  const std::vector<Eigen::Quaterniond> turn{
      Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())),
      Eigen::Quaterniond::Identity()};
  const std::vector<double> spread{0.0, 0.05};
  GaussianSampler noise(4);
  predict_segments(particles, ends, turn, spread, noise);
  double squares = 0.0;
  for (std::size_t i = 0; i < kCount; ++i) {
    const Eigen::Quaterniond q(particles.states.col(static_cast<Eigen::Index>(i)).cast<double>());
    if (i < kCount / 2) {
      EXPECT_LT(so3::angle_between(q, turn[0] * start), 1e-5);
    } else {
      squares += std::pow(so3::angle_between(q, start), 2);
    }
  }
  EXPECT_NEAR(std::sqrt(squares / (kCount / 2.0)), 0.05 * std::sqrt(3.0), 0.03 * 0.05 * 1.732);
  const std::vector<std::size_t> short_ends{kCount / 2, kCount - 1};
  EXPECT_THROW(predict_segments(particles, short_ends, turn, spread, noise), std::invalid_argument);
  const std::vector<std::size_t> unordered{kCount, kCount / 2};
  EXPECT_THROW(predict_segments(particles, unordered, turn, spread, noise), std::invalid_argument);
}

}  // namespace
}  // namespace opf
