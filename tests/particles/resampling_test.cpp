#include "opf/particles/resampling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace opf {
namespace {

using Pf = mrpt::bayes::CParticleFilter;

Eigen::VectorXd test_weights() {
  Eigen::VectorXd w(6);
  w << 0.31, 0.005, 0.17, 0.4, 0.015, 0.1;
  return w;
}

std::vector<double> copy_counts(const std::vector<std::size_t>& indices, std::size_t n) {
  std::vector<double> counts(n, 0.0);
  for (std::size_t i : indices) counts[i] += 1.0;
  return counts;
}

class ResamplingScheme : public ::testing::TestWithParam<Pf::TParticleResamplingAlgorithm> {};

// Unbiasedness: over M independent resamplings of N = 6 particles the mean copy count of particle
// i converges to N w_i. The per-draw count variance is at most the multinomial N w (1 - w) (the
// other schemes only reduce it), so 5 standard errors of the mean bound the deviation.
TEST_P(ResamplingScheme, ExpectedCopyCountsAreProportionalToWeights) {
  const Eigen::VectorXd w = test_weights();
  const std::size_t n = static_cast<std::size_t>(w.size());
  constexpr int kTrials = 40000;
  Random random(42);
  std::vector<double> total(n, 0.0);
  for (int trial = 0; trial < kTrials; ++trial) {
    const auto indices = resample_indices(w, n, GetParam(), random);
    ASSERT_EQ(indices.size(), n);
    ASSERT_TRUE(std::is_sorted(indices.begin(), indices.end()));
    const auto counts = copy_counts(indices, n);
    for (std::size_t i = 0; i < n; ++i) total[i] += counts[i];
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double expected = static_cast<double>(n) * w[Eigen::Index(i)];
    const double standard_error = std::sqrt(expected * (1.0 - w[Eigen::Index(i)]) / kTrials);
    EXPECT_NEAR(total[i] / kTrials, expected, 5.0 * standard_error) << "particle " << i;
  }
}

TEST_P(ResamplingScheme, SameSeedSameIndices) {
  const Eigen::VectorXd w = test_weights();
  Random a(7), b(7);
  EXPECT_EQ(resample_indices(w, 1000, GetParam(), a), resample_indices(w, 1000, GetParam(), b));
}

INSTANTIATE_TEST_SUITE_P(AllSchemes, ResamplingScheme,
                         ::testing::Values(Pf::prMultinomial, Pf::prResidual, Pf::prStratified,
                                           Pf::prSystematic));

TEST(Resampling, SystematicCopiesDifferFromExpectationByLessThanOne) {
  const Eigen::VectorXd w = test_weights();
  Random random(3);
  for (int trial = 0; trial < 1000; ++trial) {
    const auto counts = copy_counts(resample_indices(w, 50, Pf::prSystematic, random), 6);
    for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(counts[i] - 50.0 * w[i]), 1.0) << i;
  }
}

TEST(Resampling, ResidualKeepsTheDeterministicCopies) {
  const Eigen::VectorXd w = test_weights();
  Random random(4);
  for (int trial = 0; trial < 1000; ++trial) {
    const auto counts = copy_counts(resample_indices(w, 50, Pf::prResidual, random), 6);
    for (int i = 0; i < 6; ++i) EXPECT_GE(counts[i], std::floor(50.0 * w[i])) << i;
  }
}

TEST(Resampling, StratifiedCopiesStayWithinTwoOfExpectation) {
  const Eigen::VectorXd w = test_weights();
  Random random(5);
  for (int trial = 0; trial < 1000; ++trial) {
    const auto counts = copy_counts(resample_indices(w, 50, Pf::prStratified, random), 6);
    for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(counts[i] - 50.0 * w[i]), 2.0) << i;
  }
}

TEST(Resampling, ZeroWeightParticlesAreNeverDrawn) {
  Eigen::VectorXd w(4);
  w << 0.0, 0.5, 0.0, 0.5;
  Random random(6);
  for (auto scheme : {Pf::prMultinomial, Pf::prResidual, Pf::prStratified, Pf::prSystematic}) {
    for (std::size_t i : resample_indices(w, 200, scheme, random)) EXPECT_TRUE(i == 1 || i == 3);
  }
}

TEST(Resampling, PolicyEveryFrameOrBelowEssThreshold) {
  ResamplingOptions options;
  options.every_frame = true;
  EXPECT_TRUE(should_resample(options, 1.0));
  options.every_frame = false;
  options.ess_threshold = 0.5;
  EXPECT_FALSE(should_resample(options, 0.6));
  EXPECT_TRUE(should_resample(options, 0.4));
}

}  // namespace
}  // namespace opf
