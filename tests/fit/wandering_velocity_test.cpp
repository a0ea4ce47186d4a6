#include "opf/fit/wandering_velocity.h"

#include "opf/core/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

std::vector<double> times(double rate, double seconds) {
  std::vector<double> t;
  for (int k = 0; k <= static_cast<int>(std::lround(seconds * rate)); ++k) t.push_back(k / rate);
  return t;
}

// A velocity that wanders as white random acceleration of intensity q (m^2/s^3), sampled exactly
// (the discrete-time process a constant-velocity Kalman filter assumes): positions and velocities
// per axis.
struct Wander {
  Eigen::Matrix3Xd position;
  Eigen::Matrix3Xd velocity;
};

Wander wander(const std::vector<double>& t, double q, Random& random) {
  const auto n = static_cast<Eigen::Index>(t.size());
  Wander w{Eigen::Matrix3Xd::Zero(3, n), Eigen::Matrix3Xd::Zero(3, n)};
  for (Eigen::Index k = 1; k < n; ++k) {
    const double dt = t[static_cast<std::size_t>(k)] - t[static_cast<std::size_t>(k - 1)];
    // Cholesky factor of q [dt^3/3, dt^2/2; dt^2/2, dt].
    const double a = std::sqrt(q * dt * dt * dt / 3.0);
    const double b = q * dt * dt / 2.0 / a;
    const double c = std::sqrt(q * dt - b * b);
    for (int axis = 0; axis < 3; ++axis) {
      const double z1 = random.normal(), z2 = random.normal();
      w.position(axis, k) = w.position(axis, k - 1) + dt * w.velocity(axis, k - 1) + a * z1;
      w.velocity(axis, k) = w.velocity(axis, k - 1) + b * z1 + c * z2;
    }
  }
  return w;
}

TEST(WanderingVelocityFilter, AnExactLineIsFollowedExactly) {
  const std::vector<double> t = times(30.0, 2.0);
  const Eigen::Vector3d start(1.0, 0.0, 0.3), velocity(0.5, -0.2, 0.0);
  Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(t.size()));
  for (std::size_t k = 0; k < t.size(); ++k)
    x.col(static_cast<Eigen::Index>(k)) = start + velocity * t[k];
  const auto track =
      wandering_velocity_filter(t, x, Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(0.1));
  ASSERT_EQ(track.size(), t.size());
  for (std::size_t k = 1; k < t.size(); ++k) {
    EXPECT_LT((track[k].line.value(t[k]) - x.col(static_cast<Eigen::Index>(k))).norm(), 1e-9) << k;
    EXPECT_LT((track[k].line.rate(t[k]) - velocity).norm(), 1e-9) << k;
  }
  // One step ahead, the line is the prediction.
  EXPECT_LT((track.back().line.value(2.5) - (start + velocity * 2.5)).norm(), 1e-9);
}

// The reported velocity variance is the filter's own: on the process it assumes, the velocity's
// errors over many runs have that variance.
TEST(WanderingVelocityFilter, TheRateVarianceIsTheVelocityErrorsVariance) {
  const std::vector<double> t = times(30.0, 2.0);
  const double q = 0.5, sigma = 0.002;
  const Eigen::Vector3d noise = Eigen::Vector3d::Constant(sigma * sigma);
  double squares = 0.0, reported = 0.0;
  int count = 0;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    Random random(seed);
    const Wander truth = wander(t, q, random);
    Eigen::Matrix3Xd measured = truth.position;
    for (Eigen::Index k = 0; k < measured.cols(); ++k)
      for (int axis = 0; axis < 3; ++axis) measured(axis, k) += sigma * random.normal();
    const auto track = wandering_velocity_filter(t, measured, noise, Eigen::Vector3d::Constant(q));
    const Eigen::Vector3d error =
        track.back().line.rate(t.back()) - truth.velocity.col(measured.cols() - 1);
    squares += error.squaredNorm();
    reported += track.back().rate_variance.sum();
    count += 3;
  }
  // 1200 squared errors: their mean is known to sqrt(2 / 1200) = 4%; 15% is almost 4 sigma.
  const double ratio = squares / reported;
  EXPECT_GT(ratio, 0.85);
  EXPECT_LT(ratio, 1.15);
  EXPECT_EQ(count, 1200);
}

// A larger random acceleration is a shorter memory: after a velocity step the filter with 256
// times the intensity (a quarter of the memory) has caught up where the other still lags, and it
// pays for it with a noisier velocity while the motion is steady.
TEST(WanderingVelocityFilter, AShorterMemoryFollowsAVelocityStepSooner) {
  const std::vector<double> t = times(30.0, 1.2);
  const double sigma = 0.001;
  Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, static_cast<Eigen::Index>(t.size()));
  for (std::size_t k = 0; k < t.size(); ++k)
    x(0, static_cast<Eigen::Index>(k)) = 0.3 * std::max(0.0, t[k] - 1.0);
  const Eigen::Vector3d noise = Eigen::Vector3d::Constant(sigma * sigma);
  // Memories (noise * period / q)^(1/4) of 0.4 s and 0.1 s.
  const Eigen::Vector3d slow_q = Eigen::Vector3d::Constant(sigma * sigma / 30.0 / std::pow(0.4, 4));
  const auto slow = wandering_velocity_filter(t, x, noise, slow_q);
  const auto fast = wandering_velocity_filter(t, x, noise, 256.0 * slow_q);
  const double slow_lag = 0.3 - slow.back().line.rate(t.back())(0);
  const double fast_lag = 0.3 - fast.back().line.rate(t.back())(0);
  EXPECT_GT(slow_lag, 0.0);
  EXPECT_LT(std::abs(fast_lag), 0.3 * slow_lag);  // 0.07 against 0.26 m/s
  // Before the step (t = 1 s) the fast filter's velocity is the less certain: in the steady state
  // the velocity variance grows as q^(3/4), 64 times for 256 times q; the slow filter, not quite
  // settled after 2.5 memories, is a little less certain than that.
  const std::size_t before = 30;
  const double ratio = fast[before].rate_variance(0) / slow[before].rate_variance(0);
  EXPECT_GT(ratio, 40.0);
  EXPECT_LT(ratio, 64.0);
}

TEST(WanderingVelocityFilter, RefusesTooFewSamplesAndTimesThatDoNotIncrease) {
  const Eigen::Vector3d noise = Eigen::Vector3d::Constant(1e-6), q = Eigen::Vector3d::Ones();
  const std::vector<double> one{0.0};
  EXPECT_THROW(wandering_velocity_filter(one, Eigen::Matrix3Xd::Zero(3, 1), noise, q),
               std::invalid_argument);
  const std::vector<double> stuck{0.0, 0.1, 0.1};
  EXPECT_THROW(wandering_velocity_filter(stuck, Eigen::Matrix3Xd::Zero(3, 3), noise, q),
               std::invalid_argument);
  const std::vector<double> two{0.0, 0.1};
  EXPECT_THROW(wandering_velocity_filter(two, Eigen::Matrix3Xd::Zero(3, 3), noise, q),
               std::invalid_argument);
}

}  // namespace
}  // namespace opf
