#include "opf/particles/gaussian_sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace opf {
namespace {

constexpr std::size_t kSamples = 2000000;

std::vector<float> draw(std::uint64_t seed, std::size_t count) {
  GaussianSampler sampler(seed);
  std::vector<float> x(count);
  sampler.fill(x);
  return x;
}

// Standard normal CDF.
double phi(double x) {
  return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

TEST(GaussianSampler, SameSeedSameSamplesOtherSeedOthers) {
  EXPECT_EQ(draw(5, 1000), draw(5, 1000));
  EXPECT_NE(draw(5, 1000), draw(6, 1000));
}

// Mean, variance, skewness and excess kurtosis within 5 standard errors of N(0, 1)'s
// (standard errors 1, sqrt 2, sqrt 6 and sqrt 24 over sqrt N).
TEST(GaussianSampler, MomentsMatchTheStandardNormal) {
  const std::vector<float> x = draw(1, kSamples);
  double m1 = 0, m2 = 0, m3 = 0, m4 = 0;
  for (float v : x) {
    const double d = v;
    m1 += d;
    m2 += d * d;
    m3 += d * d * d;
    m4 += d * d * d * d;
  }
  const double n = static_cast<double>(kSamples);
  const double se = 1.0 / std::sqrt(n);
  EXPECT_NEAR(m1 / n, 0.0, 5 * se);
  EXPECT_NEAR(m2 / n, 1.0, 5 * std::sqrt(2.0) * se);
  EXPECT_NEAR(m3 / n, 0.0, 5 * std::sqrt(15.0) * se);  // var of x^3 is 15
  EXPECT_NEAR(m4 / n, 3.0, 5 * std::sqrt(96.0) * se);  // var of x^4 is 96
}

// The empirical CDF at -4 ... 4 against Phi, within 5 binomial standard errors at each point.
TEST(GaussianSampler, DistributionFunctionMatchesPhiIncludingTails) {
  std::vector<float> x = draw(2, kSamples);
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(kSamples);
  for (double t = -4.0; t <= 4.0; t += 0.5) {
    const double below =
        static_cast<double>(std::lower_bound(x.begin(), x.end(), static_cast<float>(t)) -
                            x.begin()) /
        n;
    const double p = phi(t);
    EXPECT_NEAR(below, p, 5 * std::sqrt(p * (1 - p) / n) + 1.0 / n) << "at " << t;
  }
  // 24-bit uniforms cut the tails at sqrt(2 ln 2^24) = 5.77 sigma.
  EXPECT_LE(std::max(-x.front(), x.back()), 5.78f);
}

// Samples that share a draw (the two of one Box-Muller pair, lane l and l + 16 of a block) and
// neighbours in the stream are uncorrelated, and so are their squares (the pair shares its
// radius: dependence would show there first).
TEST(GaussianSampler, PairsAndNeighboursAreUncorrelated) {
  const std::vector<float> x = draw(3, kSamples);
  const std::size_t lanes = GaussianSampler::kLanes;
  double pair = 0, pair_squares = 0, next = 0;
  std::size_t pairs = 0;
  for (std::size_t b = 0; b + GaussianSampler::kBlock <= x.size(); b += GaussianSampler::kBlock)
    for (std::size_t l = 0; l < lanes; ++l) {
      const double a = x[b + l], c = x[b + lanes + l];
      pair += a * c;
      pair_squares += (a * a - 1) * (c * c - 1);
      ++pairs;
    }
  for (std::size_t i = 0; i + 1 < x.size(); ++i) next += double(x[i]) * x[i + 1];
  const double n = static_cast<double>(pairs);
  EXPECT_NEAR(pair / n, 0.0, 5 / std::sqrt(n));
  EXPECT_NEAR(pair_squares / n, 0.0, 5 * 2 / std::sqrt(n));  // var of (a^2-1)(c^2-1) is 4
  EXPECT_NEAR(next / static_cast<double>(x.size() - 1), 0.0, 5 / std::sqrt(double(x.size())));
}

TEST(GaussianSampler, AnyLengthIsFilledWithFiniteSamples) {
  GaussianSampler sampler(4);
  for (std::size_t count : {0, 1, 15, 31, 32, 33, 1001}) {
    std::vector<float> x(count, std::nanf(""));
    sampler.fill(x);
    for (float v : x) EXPECT_TRUE(std::isfinite(v)) << count;
  }
}

}  // namespace
}  // namespace opf
