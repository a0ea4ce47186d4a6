#include "opf/permanence/covariance_inflation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opf {
namespace {

constexpr double kFrame = 1.0 / 30.0;

TEST(CovarianceInflation, GrowsByKappaPerReferenceFrameWhenStill) {
  CovarianceInflation inflation{UncertaintyOptions{}};
  for (int k = 1; k <= 60; ++k) {
    inflation.step(0.0, kFrame);
    EXPECT_NEAR(inflation.scale(), std::pow(1.03, k), 1e-9 * std::pow(1.03, k)) << k;
  }
}

TEST(CovarianceInflation, GrowsFasterTheFasterTheObjectMoves) {
  // v = speed / reference_speed = 3: alpha = kappa^3 per reference frame.
  CovarianceInflation inflation{UncertaintyOptions{}};
  for (int k = 0; k < 10; ++k) inflation.step(0.3, kFrame);
  EXPECT_NEAR(inflation.scale(), std::pow(1.03, 30), 1e-9);
}

TEST(CovarianceInflation, GrowthPerSecondDoesNotDependOnTheFrameRate) {
  CovarianceInflation at_30{UncertaintyOptions{}}, at_100{UncertaintyOptions{}};
  for (int k = 0; k < 30; ++k) at_30.step(0.2, 1.0 / 30.0);
  for (int k = 0; k < 100; ++k) at_100.step(0.2, 1.0 / 100.0);
  EXPECT_NEAR(at_30.scale(), at_100.scale(), 1e-9 * at_30.scale());
}

TEST(CovarianceInflation, ResetReturnsToQ) {
  CovarianceInflation inflation{UncertaintyOptions{}};
  inflation.step(1.0, 1.0);
  EXPECT_GT(inflation.scale(), 1.0);
  inflation.reset();
  EXPECT_EQ(inflation.scale(), 1.0);
}

TEST(CovarianceInflation, LongOcclusionIsCappedAndReported) {
  UncertaintyOptions options;
  options.max_scale = 1e3;
  CovarianceInflation inflation(options);
  for (int k = 0; k < 100000; ++k) inflation.step(50.0, kFrame);
  EXPECT_EQ(inflation.scale(), 1e3);
  EXPECT_TRUE(inflation.capped());
  EXPECT_TRUE(std::isfinite(inflation.scale()));
}

TEST(CovarianceInflation, RejectsKappaNotAboveOne) {
  UncertaintyOptions options;
  options.kappa = 1.0;
  EXPECT_THROW(CovarianceInflation{options}, std::invalid_argument);
  options = {};
  options.reference_speed = 0.0;
  EXPECT_THROW(CovarianceInflation{options}, std::invalid_argument);
}

}  // namespace
}  // namespace opf
