#include "opf/permanence/mixture_particle_motion.h"

#include "opf/core/random.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

constexpr double kRate = 30.0;         // Hz
constexpr std::size_t kCount = 20000;  // particles per portion

// Banks that saw a second of an object moving along x at 0.5 m/s, falling along z under gravity
// from rest, still along y, turning at `rate` rad/s about the body z axis, measured with 2 mm and
// 0.01 rad of noise (seeded).
struct Seen {
  MotionModelBank translation;
  RotationModelBank rotation;
  Eigen::Vector3d position;
  Eigen::Quaterniond orientation;
};

Seen seen(double rate, const MotionModelBankOptions& options = {}) {
  RotationModelBankOptions rotation_options;
  rotation_options.observation_noise = 0.01;
  Seen s{MotionModelBank(options), RotationModelBank(rotation_options), {}, {}};
  Random random(11);
  for (int k = 0; k <= 30; ++k) {
    const double t = k / kRate;
    s.position = {0.5 * t, 0.2, 1.0 - 0.5 * 9.81 * t * t};
    s.orientation = so3::exp(Eigen::Vector3d(0.0, 0.0, rate * t));
    const Eigen::Vector3d noise(random.normal(), random.normal(), random.normal());
    const Eigen::Vector3d turn(random.normal(), random.normal(), random.normal());
    s.translation.update(t, s.position + 0.002 * noise);
    s.rotation.update(t, s.orientation * so3::exp(0.01 * turn));
  }
  return s;
}

PoseParticleFilter cloud_at(const Seen& s) {
  PoseParticleFilterOptions options;
  options.translation_particles = options.rotation_particles = kCount;
  PoseParticleFilter filter(options, 5);
  filter.initialise(s.position, s.orientation);
  return filter;
}

// The cloud's mean and variance per axis (equal weights: nothing reweights while it follows).
void moments(const PoseParticleFilter& f, Eigen::Vector3d& mean, Eigen::Vector3d& variance) {
  const auto& states = f.translation().states;
  mean = states.rowwise().mean();
  variance = (states.colwise() - mean).array().square().rowwise().mean();
}

// At any horizon the cloud is the one at onset plus the mixture's motion and spread since then:
// mean0 + sum_j w_j d_j and var0 + sum_j w_j (P_j(h) - P_j(0)) + the spread of the d_j, with
// d_j = m_j(h) - m_j(0). Checked after six steps to 0.2 s, within 5 standard errors of a mean
// and 5 of a variance (sqrt(2 / N) of it) for 20000 particles.
TEST(MixtureParticleMotion, TheCloudIsTheMixturesPrediction) {
  const Seen s = seen(0.0);
  PoseParticleFilter filter = cloud_at(s);
  Eigen::Vector3d mean0, variance0;
  moments(filter, mean0, variance0);
  MixtureParticleMotion motion(3);
  motion.start(s.translation, s.rotation, filter);
  const double h = 0.2;
  for (int k = 0; k < 6; ++k)
    motion.advance(s.translation, s.rotation, k * h / 6.0, (k + 1) * h / 6.0, filter);
  Eigen::Vector3d mean, variance;
  moments(filter, mean, variance);
  for (int axis = 0; axis < 3; ++axis) {
    double shift = 0.0, second = 0.0, spread = 0.0;
    for (std::size_t j = 0; j < s.translation.members(axis).size(); ++j) {
      const MemberPrediction from = s.translation.member_prediction(axis, j, 0.0);
      const MemberPrediction to = s.translation.member_prediction(axis, j, h);
      const double d = to.mean - from.mean;
      shift += to.weight * d;
      second += to.weight * d * d;
      spread += to.weight * (to.variance - from.variance);
    }
    const double expected_variance = variance0[axis] + spread + second - shift * shift;
    const double n = static_cast<double>(kCount);
    EXPECT_NEAR(mean[axis], mean0[axis] + shift, 5.0 * std::sqrt(expected_variance / n))
        << "axis " << axis;
    EXPECT_NEAR(variance[axis], expected_variance, 5.0 * std::sqrt(2.0 / n) * expected_variance)
        << "axis " << axis;
  }
  // Along x the object moves 0.1 m in the 0.2 s, along z it falls 0.5 g (1.2^2 - 1^2) = 2.16 m
  // (the ballistic members): the mixture carries the cloud there, not where it was.
  EXPECT_NEAR(mean.x() - mean0.x(), 0.1, 0.01);
  EXPECT_NEAR(mean.z() - mean0.z(), -0.5 * 9.81 * (1.2 * 1.2 - 1.0), 0.02);
  EXPECT_NEAR(mean.y() - mean0.y(), 0.0, 0.005);
}

// A turning object (1.5 rad/s) is turned on by its constant-angular-velocity members: 0.3 rad in
// 0.2 s, within 0.02 rad (the rate's estimate from a second of 0.01 rad noise and the cloud's own
// spread); a bank of constant orientation only holds it.
TEST(MixtureParticleMotion, RotationParticlesTurnWithTheirMembers) {
  const Seen s = seen(1.5);
  const auto turned = [&](const RotationModelBank& rotation) {
    PoseParticleFilter filter = cloud_at(s);
    MixtureParticleMotion motion(3);
    motion.start(s.translation, rotation, filter);
    motion.advance(s.translation, rotation, 0.0, 0.1, filter);
    motion.advance(s.translation, rotation, 0.1, 0.2, filter);
    return so3::angle_between(filter.rotation_moments().mean, s.orientation);
  };
  EXPECT_NEAR(turned(s.rotation), 0.3, 0.02);
  RotationModelBankOptions still;
  still.constant_angular_velocity = false;
  still.observation_noise = 0.01;
  RotationModelBank held(still);
  held.update(1.0, s.orientation);
  EXPECT_LT(turned(held), 0.02);
}

// Grouping the rotation particles by member at onset reorders them, weights and all: the same set
// of (quaternion, weight) pairs before and after.
TEST(MixtureParticleMotion, GroupingByMemberKeepsTheParticlesAndTheirWeights) {
  const Seen s = seen(1.0);
  PoseParticleFilter filter = cloud_at(s);
  filter.predict(0.5);  // distinct particles
  Eigen::VectorXd& log_weights = filter.rotation().weights.log();
  for (Eigen::Index i = 0; i < log_weights.size(); ++i) log_weights[i] = -1e-4 * double(i);
  const auto pairs = [&] {
    std::vector<std::array<double, 5>> p;
    const auto& states = filter.rotation().states;
    for (Eigen::Index i = 0; i < states.cols(); ++i)
      p.push_back({states(0, i), states(1, i), states(2, i), states(3, i),
                   filter.rotation().weights.log()[i]});
    std::sort(p.begin(), p.end());
    return p;
  };
  const auto before = pairs();
  MixtureParticleMotion motion(2);
  motion.start(s.translation, s.rotation, filter);
  EXPECT_EQ(pairs(), before);
}

TEST(MixtureParticleMotion, TheSameSeedMovesTheSameParticles) {
  const Seen s = seen(1.0);
  const auto run = [&](std::uint64_t seed) {
    PoseParticleFilter filter = cloud_at(s);
    MixtureParticleMotion motion(seed);
    motion.start(s.translation, s.rotation, filter);
    motion.advance(s.translation, s.rotation, 0.0, 0.5, filter);
    return filter.translation().states;
  };
  EXPECT_TRUE(run(4) == run(4));
  EXPECT_FALSE(run(4) == run(5));
}

TEST(MixtureParticleMotion, RefusesStepsOutOfOrderAndUnstartedClouds) {
  const Seen s = seen(0.0);
  PoseParticleFilter filter = cloud_at(s);
  MixtureParticleMotion motion(1);
  EXPECT_THROW(motion.advance(s.translation, s.rotation, 0.0, 0.1, filter), std::logic_error);
  motion.start(s.translation, s.rotation, filter);
  EXPECT_THROW(motion.advance(s.translation, s.rotation, 0.2, 0.1, filter), std::invalid_argument);
  EXPECT_THROW(motion.start(MotionModelBank(), s.rotation, filter), std::logic_error);
}

}  // namespace
}  // namespace opf
