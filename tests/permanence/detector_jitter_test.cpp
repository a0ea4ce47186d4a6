#include "opf/permanence/detector_jitter.h"

#include "opf/core/random.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace opf {
namespace {

// A body turning at 2 rad/s about a tilted axis, measured at 30 Hz with `sigma` rad of tangent
// noise per body axis (`per_axis` scales each axis's share).
DetectorJitter measured_turn(double sigma, const Eigen::Vector3d& per_axis, std::uint64_t seed,
                             int frames = 60, double window = 2.0) {
  Random random(seed);
  DetectorJitter jitter(window);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();
  for (int k = 0; k < frames; ++k) {
    const double t = k / 30.0;
    const Eigen::Vector3d e(random.normal(), random.normal(), random.normal());
    jitter.add(t, Eigen::Vector3d::Zero(),
               so3::exp(2.0 * t * axis) * so3::exp(sigma * per_axis.cwiseProduct(e)));
  }
  return jitter;
}

// The turn itself is no noise: 0.01 rad of white noise on every axis reads as 0.01 rad. The median
// of 58 squares knows each axis's sigma to about +-15% (one standard deviation), and the largest
// of three such estimates lies above the truth by about 0.85 of that (the mean of the largest of
// three standard normals), plus the median's skew: 1.13-1.2 sigma on average, on the side of
// caution (a likelihood a little wide, never one narrower than the noise).
TEST(DetectorJitter, ReadsTheRotationNoiseNotTheTurn) {
  double sum = 0.0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    DetectorJitter jitter = measured_turn(0.01, Eigen::Vector3d::Ones(), seed);
    const auto sigma = jitter.rotation_sigma();
    ASSERT_TRUE(sigma);
    EXPECT_GT(*sigma, 0.007) << seed;
    EXPECT_LT(*sigma, 0.018) << seed;
    sum += *sigma / 40.0;
  }
  EXPECT_GT(sum, 0.0108);
  EXPECT_LT(sum, 0.0125);
}

// The position's second differences read the detector's position noise, not the motion: a hand
// sweeping a circle of 0.3 m radius in 6 s (its acceleration, 0.33 m/s^2, moves a second
// difference by 0.37 mm at 30 Hz),
// measured with 2 mm of white noise per axis, reads as 2 mm, with the rotation's spread over seeds
// (the noisiest of three axes, 1.13-1.2 sigma on average).
TEST(DetectorJitter, ReadsThePositionNoiseNotTheMotion) {
  double sum = 0.0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Random random(seed);
    DetectorJitter jitter(2.0);
    for (int k = 0; k < 60; ++k) {
      const double t = k / 30.0;
      const Eigen::Vector3d path(0.3 * std::cos(M_PI * t / 3), 0.3 * std::sin(M_PI * t / 3), 0.1);
      const Eigen::Vector3d noise(random.normal(), random.normal(), random.normal());
      jitter.add(t, path + 0.002 * noise, Eigen::Quaterniond::Identity());
    }
    const auto sigma = jitter.translation_sigma();
    ASSERT_TRUE(sigma);
    EXPECT_GT(*sigma, 0.0014) << seed;
    EXPECT_LT(*sigma, 0.0036) << seed;
    EXPECT_EQ(*jitter.rotation_sigma(), 0.0) << seed;  // the orientation never changed
    sum += *sigma / 40.0;
  }
  EXPECT_GT(sum, 0.00216);
  EXPECT_LT(sum, 0.0025);
}

// The likelihood has one spread for all three axes: the noisiest axis sets it (in-plane angles
// from image moments jitter about one axis only).
TEST(DetectorJitter, TheNoisiestAxisSetsTheSpread) {
  double sum = 0.0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    DetectorJitter jitter = measured_turn(0.02, Eigen::Vector3d(0.0, 0.0, 1.0), seed);
    sum += jitter.rotation_sigma().value() / 40.0;
  }
  EXPECT_NEAR(sum, 0.02, 0.002);
}

// Eight differences are needed (ten consecutive frames); a gap restarts the differences, and
// differences older than the window are forgotten.
TEST(DetectorJitter, NeedsEightDifferencesAcrossNoGap) {
  DetectorJitter nine = measured_turn(0.01, Eigen::Vector3d::Ones(), 1, 9);
  EXPECT_FALSE(nine.rotation_sigma());
  DetectorJitter ten = measured_turn(0.01, Eigen::Vector3d::Ones(), 1, 10);
  EXPECT_TRUE(ten.rotation_sigma());

  // Frames 0-5 give 4 differences; after the gap (frames 6-9 missing) the intervals differ twice,
  // so frames 10-14 give 3 and frame 15 the eighth.
  DetectorJitter gapped(2.0);
  Random random(2);
  for (const int k : {0, 1, 2, 3, 4, 5, 10, 11, 12, 13, 14})
    gapped.add(k / 30.0, Eigen::Vector3d::Zero(),
               so3::exp(0.01 * Eigen::Vector3d(random.normal(), random.normal(), random.normal())));
  EXPECT_FALSE(gapped.rotation_sigma());
  gapped.add(15 / 30.0, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity());
  EXPECT_TRUE(gapped.rotation_sigma());
  DetectorJitter windowed = measured_turn(0.01, Eigen::Vector3d::Ones(), 3, 60, 0.2);
  EXPECT_FALSE(windowed.rotation_sigma());  // 0.2 s at 30 Hz holds 6 or 7 differences
}

// The median read every frame is the one a selection over the window's differences gives, to the
// bit, as the window slides: turns about one axis on a 1 mrad grid give many equal squares, so
// removing the oldest must take out one copy of its value, not any other. A measurement with NaN
// adds no difference (the three it touches are skipped) and leaves the later reads intact.
TEST(DetectorJitter, TheMedianFollowsTheSlidingWindowExactly) {
  constexpr double kWindow = 0.5;
  Random random(5);
  DetectorJitter jitter(kWindow);
  std::vector<double> times;
  std::vector<Eigen::Quaterniond> orientations;
  for (int k = 0; k < 120; ++k) {
    const double t = k / 30.0;
    const double angle = std::round((0.5 * t + 0.002 * random.normal()) * 1000.0) / 1000.0;
    Eigen::Quaterniond q = so3::exp(Eigen::Vector3d(0.0, 0.0, angle));
    if (k == 60) q.x() = std::numeric_limits<double>::quiet_NaN();
    jitter.add(t, Eigen::Vector3d::Zero(), q);
    times.push_back(t);
    orientations.push_back(q.normalized());
    if (k < 20) continue;
    // The differences still in the window, each as the class forms it: turn minus previous turn.
    double largest = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> squares;
      for (int j = 2; j <= k; ++j) {
        if (t - times[static_cast<std::size_t>(j)] > kWindow) continue;
        const auto at = [&](int i) { return orientations[static_cast<std::size_t>(i)]; };
        const Eigen::Vector3d d =
            so3::difference(at(j - 1), at(j)) - so3::difference(at(j - 2), at(j - 1));
        if (d.allFinite()) squares.push_back(d(axis) * d(axis));
      }
      const auto middle = squares.begin() + static_cast<std::ptrdiff_t>(squares.size() / 2);
      std::nth_element(squares.begin(), middle, squares.end());
      largest = std::max(largest, *middle);
    }
    const auto read = jitter.rotation_sigma();
    ASSERT_TRUE(read) << "frame " << k;
    EXPECT_EQ(*read, std::sqrt(largest / (6.0 * 0.4549))) << "frame " << k;
  }
}

}  // namespace
}  // namespace opf
