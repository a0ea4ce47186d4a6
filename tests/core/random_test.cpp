#include "opf/core/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace opf {
namespace {

TEST(Random, SameSeedSameSequenceDifferentSeedDifferent) {
  Random a(11), b(11), c(12);
  for (int i = 0; i < 100; ++i) {
    const auto x = a.next();
    EXPECT_EQ(x, b.next());
    EXPECT_NE(x, c.next());
  }
}

TEST(Random, UniformIsInUnitIntervalWithMeanOneHalf) {
  Random random(1);
  constexpr int kN = 200000;
  double sum = 0.0;
  for (int i = 0; i < kN; ++i) {
    const double u = random.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  // Var(U) = 1/12: 5 standard errors.
  EXPECT_NEAR(sum / kN, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / kN));
}

TEST(Random, NormalHasUnitMomentsAndGaussianTails) {
  Random random(2);
  constexpr std::size_t kN = 400000;
  std::vector<double> x(kN);
  random.fill_normal(x);
  double sum = 0.0, squares = 0.0, beyond_two = 0.0;
  for (double v : x) {
    sum += v;
    squares += v * v;
    beyond_two += std::abs(v) > 2.0;
  }
  const double n = static_cast<double>(kN);
  EXPECT_NEAR(sum / n, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(squares / n, 1.0, 5.0 * std::sqrt(2.0 / n));  // Var(X^2) = 2
  const double p = 0.0455003;                               // P(|X| > 2)
  EXPECT_NEAR(beyond_two / n, p, 5.0 * std::sqrt(p * (1 - p) / n));
}

TEST(Random, DerivedSeedsAreDistinctAndReproducible) {
  EXPECT_EQ(derive_seed(5, 0), derive_seed(5, 0));
  EXPECT_NE(derive_seed(5, 0), derive_seed(5, 1));
  EXPECT_NE(derive_seed(5, 0), derive_seed(6, 0));
}

}  // namespace
}  // namespace opf
