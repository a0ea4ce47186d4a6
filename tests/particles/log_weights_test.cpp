#include "opf/particles/log_weights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace opf {
namespace {

TEST(LogWeights, NormaliseMakesLinearWeightsSumToOneWithoutUnderflow) {
  LogWeights w(3);
  // exp(-2000) underflows to 0 in double; log-sum-exp must still recover the ratios 1 : e : e^2.
  w.log() << -2002.0, -2001.0, -2000.0;
  ASSERT_TRUE(w.normalise());
  const Eigen::VectorXd linear = w.linear();
  EXPECT_NEAR(linear.sum(), 1.0, 1e-15);
  const double e = std::exp(1.0);
  EXPECT_NEAR(linear[0], 1.0 / (1.0 + e + e * e), 1e-15);
  EXPECT_NEAR(linear[2] / linear[1], e, 1e-12);
}

TEST(LogWeights, AllWeightsVanishedRecoversToUniform) {
  LogWeights w(4);
  w.log().setConstant(-std::numeric_limits<double>::infinity());
  EXPECT_FALSE(w.normalise());
  for (double v : w.linear()) EXPECT_DOUBLE_EQ(v, 0.25);

  w.log() << 0.0, std::nan(""), -1.0, -2.0;
  EXPECT_FALSE(w.normalise());
  for (double v : w.linear()) EXPECT_DOUBLE_EQ(v, 0.25);
}

// Every write access moves the generation on; reading does not (what was read at a generation
// holds while it stays).
TEST(LogWeights, WritesMoveTheGenerationOnReadsDoNot) {
  LogWeights w(3);
  const LogWeights& read = w;
  std::uint64_t last = w.generation();
  const auto moved = [&] {
    const bool on = w.generation() > last;
    last = w.generation();
    return on;
  };
  EXPECT_EQ(read.log().size(), 3);
  (void)read.effective_sample_fraction();
  (void)read.linear();
  EXPECT_FALSE(moved());
  w.log()[0] = -1.0;
  EXPECT_TRUE(moved());
  w.add(Eigen::Vector3d(0.0, -1.0, -2.0));
  EXPECT_TRUE(moved());
  EXPECT_TRUE(w.normalise());
  EXPECT_TRUE(moved());
  bool accumulate = false;
  w.for_likelihood(accumulate);
  EXPECT_TRUE(moved());
  w.reset();
  EXPECT_TRUE(moved());
}

TEST(LogWeights, EffectiveSampleFraction) {
  LogWeights w(4);
  w.reset();
  EXPECT_DOUBLE_EQ(w.effective_sample_fraction(), 1.0);
  // One particle carries everything: ESS = 1 particle out of 4.
  w.log() << 0.0, -1e6, -1e6, -1e6;
  EXPECT_NEAR(w.effective_sample_fraction(), 0.25, 1e-15);
  // Two equal particles out of four.
  w.log() << -3.0, -3.0, -1e6, -1e6;
  EXPECT_NEAR(w.effective_sample_fraction(), 0.5, 1e-15);
}

TEST(LogWeights, AddMultipliesLikelihoods) {
  LogWeights w(2);
  w.reset();
  Eigen::VectorXd log_likelihood(2);
  log_likelihood << std::log(3.0), std::log(1.0);
  w.add(log_likelihood);
  ASSERT_TRUE(w.normalise());
  EXPECT_NEAR(w.linear()[0], 0.75, 1e-15);
}

}  // namespace
}  // namespace opf
