#include "opf/permanence/hypothesis_probabilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

using Order = std::vector<std::size_t>;

// The prior splits one: left 2/3, the carried third shared by the plausible occluders.
TEST(HypothesisProbabilities, ThePriorIsTwoToOneForLeft) {
  EXPECT_DOUBLE_EQ(kLeftPrior / (1.0 - kLeftPrior), 2.0);
  EXPECT_DOUBLE_EQ(kSubstantialBayesFactor * kSubstantialBayesFactor, 10.0);
}

// A place out of view says nothing; one in clear view with no detection keeps P_miss = 0.1 of
// its probability; half seen, 1 - 0.5 * 0.9.
TEST(HypothesisProbabilities, NoDetectionLikelihoodFallsWithTheChanceOfBeingSeen) {
  EXPECT_DOUBLE_EQ(no_detection_likelihood(0.0), 1.0);
  EXPECT_DOUBLE_EQ(no_detection_likelihood(1.0), kDetectorMissProbability);
  EXPECT_DOUBLE_EQ(no_detection_likelihood(0.5), 0.55);
}

// Another hypothesis must be sqrt(10) = 3.16 times as probable as the main one to lead: 0.7
// against 0.3 (2.3 times) leaves the main one first; 0.8 against 0.2 (4 times) does not.
TEST(HypothesisProbabilities, TheMainEstimateChangesHandsOnSubstantialEvidenceOnly) {
  EXPECT_EQ(hypothesis_order(std::vector{0.3, 0.7}), (Order{0, 1}));
  EXPECT_EQ(hypothesis_order(std::vector{0.2, 0.8}), (Order{1, 0}));
  // At the factor exactly it leads; just short of it, not.
  EXPECT_EQ(hypothesis_order(std::vector{0.25, 0.25 * kSubstantialBayesFactor}), (Order{1, 0}));
  EXPECT_EQ(hypothesis_order(std::vector{0.25, 0.25 * kSubstantialBayesFactor * (1.0 - 1e-12)}),
            (Order{0, 1}));
}

// It is the most probable other that is weighed against the main one, whatever the others: the
// cups game's ball, left (0.05) with cup B's carry (0.9) and its hand's (0.05), is cup B's.
TEST(HypothesisProbabilities, TheMostProbableOtherIsWeighedAgainstTheMainOne) {
  EXPECT_EQ(hypothesis_order(std::vector{0.05, 0.9, 0.05}), (Order{1, 0, 2}));
  EXPECT_EQ(hypothesis_order(std::vector{0.05, 0.05, 0.9}), (Order{2, 0, 1}));
  EXPECT_EQ(hypothesis_order(std::vector{0.04, 0.02, 0.9, 0.04}), (Order{2, 0, 3, 1}));
  // Kept: the others still follow it, most probable first.
  EXPECT_EQ(hypothesis_order(std::vector{0.4, 0.1, 0.3, 0.2}), (Order{0, 2, 3, 1}));
}

// Ties keep their order, the main one included.
TEST(HypothesisProbabilities, TiesKeepTheirOrder) {
  EXPECT_EQ(hypothesis_order(std::vector{0.5, 0.25, 0.25}), (Order{0, 1, 2}));
  EXPECT_EQ(hypothesis_order(std::vector{0.1, 0.45, 0.45}), (Order{1, 2, 0}));
}

// Below 10^-3 a hypothesis is dropped, the first kept whatever its probability; a main one
// replaced is dropped like any other.
TEST(HypothesisProbabilities, NegligibleHypothesesAreDroppedButTheFirstIsKept) {
  EXPECT_EQ(hypothesis_order(std::vector{0.9985, 0.0005, 0.001}), (Order{0, 2}));
  EXPECT_EQ(hypothesis_order(std::vector{0.0005, 0.9995}), (Order{1}));
  EXPECT_EQ(hypothesis_order(std::vector{1.0}), (Order{0}));
  EXPECT_TRUE(hypothesis_order(std::vector<double>{}).empty());
}

// The reveal: probability times evidence. Left at 0.9 whose place is 100 times less likely to
// give the measurement than the carried one's (0.1) loses to it; equal posteriors keep the first.
TEST(HypothesisProbabilities, TheRevealTakesProbabilityTimesEvidence) {
  EXPECT_EQ(most_probable_given(std::vector{0.9, 0.1}, std::vector{std::log(0.01), 0.0}), 1u);
  EXPECT_EQ(most_probable_given(std::vector{0.9, 0.1}, std::vector{std::log(0.5), 0.0}), 0u);
  EXPECT_EQ(most_probable_given(std::vector{0.5, 0.5}, std::vector{-2.0, -2.0}), 0u);
  EXPECT_EQ(most_probable_given(std::vector{0.2, 0.3, 0.5}, std::vector{-1.0, -1.0, -9.0}), 1u);
  EXPECT_THROW(most_probable_given(std::vector<double>{}, std::vector<double>{}),
               std::invalid_argument);
  EXPECT_THROW(most_probable_given(std::vector{1.0}, std::vector{0.0, 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace opf
