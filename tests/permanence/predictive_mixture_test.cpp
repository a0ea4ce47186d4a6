#include "opf/permanence/predictive_mixture.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

// 0.25 N(1, 0.5) + 0.75 N(3, 1): mean 2.5, variance 0.25 (0.5 + 2.25) + 0.75 (1 + 0.25) = 1.625.
TEST(AxisMixture, MomentsAreTheLawOfTotalVariance) {
  AxisMixture mixture;
  mixture.members = {{"a", 0.25, 1.0, 0.5}, {"b", 0.75, 3.0, 1.0}};
  EXPECT_DOUBLE_EQ(mixture.mean(), 2.5);
  EXPECT_DOUBLE_EQ(mixture.variance(), 1.625);
}

}  // namespace
}  // namespace opf
