// The weight kernels: log-domain normalisation, resampling weights and the ESS fraction.

#include "opf/particles/weight_kernels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace opf {
namespace {

TEST(WeightKernels, NormalisationAndResamplingWeights) {
  const std::size_t n = 1000;
  std::vector<double> log_w(n), linear(n);
  for (std::size_t i = 0; i < n; ++i) log_w[i] = -1000.0 - 0.01 * static_cast<double>(i);
  std::vector<double> original = log_w;
  std::vector<float> relative(n);
  const kernels::NormalisedWeights fast =
      kernels::resampling_weights(log_w.data(), relative.data(), n);
  const kernels::NormalisedWeights exact =
      kernels::normalise_log_weights(log_w.data(), linear.data(), n);
  ASSERT_TRUE(exact.usable);
  ASSERT_TRUE(fast.usable);
  double sum = 0.0, sum_squares = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = std::exp(original[i] - original[0]);
    sum += w;
    sum_squares += w * w;
    // The exponent is rounded to float first: relative error |x| 2^-24 plus the exp's own.
    const double x = original[i] - original[0];
    EXPECT_NEAR(relative[i], w, (std::abs(x) + 2.0) * 1.2e-7 * w);
  }
  const double ess = sum * sum / (static_cast<double>(n) * sum_squares);
  EXPECT_NEAR(exact.ess_fraction, ess, 1e-14);
  EXPECT_NEAR(fast.ess_fraction, ess, 1e-6);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(linear[i], std::exp(original[i] - original[0]) / sum, 1e-15);
    EXPECT_NEAR(std::exp(log_w[i]), linear[i], 1e-15);
  }
  log_w.assign(n, -std::numeric_limits<double>::infinity());
  EXPECT_FALSE(kernels::normalise_log_weights(log_w.data(), linear.data(), n).usable);
  EXPECT_FALSE(kernels::resampling_weights(log_w.data(), relative.data(), n).usable);
  log_w.assign(n, 0.0);
  log_w[500] = std::nan("");
  EXPECT_FALSE(kernels::normalise_log_weights(log_w.data(), linear.data(), n).usable);
  EXPECT_FALSE(kernels::resampling_weights(log_w.data(), relative.data(), n).usable);
}

}  // namespace
}  // namespace opf
