#include "opf/permanence/weighted_choice.h"

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

// Weights (0.1, 0, 0.3, 0.6): [0, 0.1) -> 0, [0.1, 0.4) -> 2, [0.4, 1) -> 3. A stratified grid of
// 1000 draws (k + 0.5) / 1000 falls 100, 0, 300, 600 times on them: exactly the weights' shares.
TEST(WeightedChoice, MapsUniformDrawsInProportionToTheWeights) {
  const std::vector<double> weights = {0.1, 0.0, 0.3, 0.6};
  std::array<int, 4> counts{};
  for (int k = 0; k < 1000; ++k) ++counts[weighted_choice(weights, (k + 0.5) / 1000.0)];
  EXPECT_EQ(counts, (std::array<int, 4>{100, 0, 300, 600}));
  EXPECT_EQ(weighted_choice(weights, 0.0), 0u);
  EXPECT_EQ(weighted_choice(weights, 0.0999), 0u);
  EXPECT_EQ(weighted_choice(weights, 0.1001), 2u);
  EXPECT_EQ(weighted_choice(weights, 0.3999), 2u);
  EXPECT_EQ(weighted_choice(weights, 0.4001), 3u);
  EXPECT_EQ(weighted_choice(weights, 1.0), 3u);  // clamped, the last positive weight
  EXPECT_EQ(weighted_choice(weights, -0.5), 0u);
}

// Unnormalised weights take their shares of the sum; a trailing zero weight is never chosen.
TEST(WeightedChoice, NormalisesAndSkipsZeroWeights) {
  const std::vector<double> weights = {2.0, 6.0, 0.0};
  EXPECT_EQ(weighted_choice(weights, 0.2499), 0u);
  EXPECT_EQ(weighted_choice(weights, 0.2501), 1u);
  EXPECT_EQ(weighted_choice(weights, 1.0), 1u);
}

TEST(WeightedChoice, RejectsWeightsWithoutMass) {
  EXPECT_THROW(weighted_choice(std::vector<double>{}, 0.5), std::invalid_argument);
  EXPECT_THROW(weighted_choice(std::vector<double>{0.0, 0.0}, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace opf
