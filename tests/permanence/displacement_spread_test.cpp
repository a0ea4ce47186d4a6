#include "opf/permanence/displacement_spread.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

double squared(double x) {
  return x * x;
}

// A line at 0.2 m/s along x, measured at 30 Hz for 5 s with a second missing in the middle: at
// each lag the mean squared displacement is (0.2 lag)^2 on x and zero on the still axes. Near the
// gap a pair's own lag may differ from its bin's by up to a quarter; the profile's lag is the
// pairs' mean, so the line's squares sit within 2% of it (1.25% at 2 s).
TEST(DisplacementSpread, ReadsHowFarTheObjectMovesInAGivenTime) {
  DisplacementSpread spread;
  for (int k = 0; k <= 150; ++k) {
    if (k > 60 && k < 90) continue;
    const double t = k / 30.0;
    spread.add(t, {0.2 * t, 0.5, 1.0});
  }
  const DisplacementProfile p = spread.profile();
  ASSERT_EQ(p.lags.size(), DisplacementSpread::kLags.size());
  for (std::size_t b = 0; b < p.lags.size(); ++b) {
    EXPECT_NEAR(p.lags[b], DisplacementSpread::kLags[b], 0.25 * DisplacementSpread::kLags[b]);
    EXPECT_NEAR(p.mean_squares[b].x(), squared(0.2 * p.lags[b]), 0.02 * squared(0.2 * p.lags[b]));
    EXPECT_EQ(p.mean_squares[b].y(), 0.0);
    EXPECT_EQ(p.mean_squares[b].z(), 0.0);
  }
  // Read between the lags held, linearly; beyond the longest, in proportion to the lag.
  const double mid = 0.5 * (p.lags[2] + p.lags[3]);
  EXPECT_DOUBLE_EQ(p.at(mid).x(), 0.5 * (p.mean_squares[2].x() + p.mean_squares[3].x()));
  EXPECT_DOUBLE_EQ(p.at(2.0 * p.lags.back()).x(), 2.0 * p.mean_squares.back().x());
  EXPECT_DOUBLE_EQ(p.at(0.5 * p.lags.front()).x(), 0.5 * p.mean_squares.front().x());
}

// Still before and after a 1.5 s gap, moved 10 cm while hidden: only pairs across the gap see
// the move, and they count. At 2 s (1.5-2.5 s apart), the 31 measurements of the first second
// after the gap pair with ones before it; 47 other pairs lie on one side (78 at 30 Hz).
TEST(DisplacementSpread, WhatTheObjectDidWhileHiddenCounts) {
  DisplacementSpread spread;
  for (int k = 0; k <= 180; ++k) {
    const double t = k / 30.0;
    if (t > 2.0 + 1e-9 && t < 3.5 - 1e-9) continue;
    spread.add(t, {t < 3.0 ? 0.0 : 0.1, 0.0, 0.0});
  }
  const DisplacementProfile p = spread.profile();
  ASSERT_EQ(p.lags.size(), DisplacementSpread::kLags.size());
  EXPECT_NEAR(p.mean_squares[4].x(), 31.0 / 78.0 * squared(0.1), 1e-12);
  // Pairs a quarter second apart never straddle a 1.5 s gap: nothing moved.
  EXPECT_EQ(p.mean_squares[1].x(), 0.0);
}

TEST(DisplacementSpread, TooFewPairsSayNothing) {
  DisplacementSpread spread;
  for (int k = 0; k < 4; ++k) spread.add(0.125 * k, {0.1 * k, 0.0, 0.0});
  EXPECT_TRUE(spread.profile().empty());
  EXPECT_EQ(spread.profile().at(1.0), Eigen::Vector3d::Zero());
  for (int k = 4; k < 12; ++k) spread.add(0.125 * k, {0.1 * k, 0.0, 0.0});
  EXPECT_FALSE(spread.profile().empty());
  spread.clear();
  EXPECT_TRUE(spread.profile().empty());
}

}  // namespace
}  // namespace opf
