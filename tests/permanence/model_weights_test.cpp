#include "opf/permanence/model_weights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

// Priors are normalised; equal log-likelihoods leave the weights where they are.
TEST(ModelWeights, StartAtThePriors) {
  ModelWeights w({1.0, 3.0});
  EXPECT_NEAR(w.weights()[0], 0.25, 1e-15);
  EXPECT_NEAR(w.weights()[1], 0.75, 1e-15);
  const std::vector<double> equal = {-4.0, -4.0};
  w.update(0.1, 1.0, equal);
  EXPECT_NEAR(w.weights()[0], 0.25, 1e-15);
}

// One step: log w_j <- lambda log w_j + (1 - lambda) log pi_j + l_j, normalised. From the prior
// (1/2, 1/2) with l = (0, -1): w = (1, e^-1) / (1 + e^-1).
TEST(ModelWeights, AddTheLogLikelihoods) {
  ModelWeights w({1.0, 1.0});
  const std::vector<double> l = {0.0, -1.0};
  w.update(1.0 / 30.0, 1.0, l);
  EXPECT_NEAR(w.weights()[1], std::exp(-1.0) / (1.0 + std::exp(-1.0)), 1e-15);
}

// The forgetting is stated in continuous time: with no evidence, two steps of dt / 2 forget as
// one of dt; over a long gap the weights return to the priors.
TEST(ModelWeights, ForgetInContinuousTime) {
  ModelWeights halves({1.0, 2.0, 1.0}), whole({1.0, 2.0, 1.0});
  const std::vector<double> evidence = {0.0, -3.0, -6.0}, none = {0.0, 0.0, 0.0};
  halves.update(0.1, 1.0, evidence);
  whole.update(0.1, 1.0, evidence);
  halves.update(0.25, 1.0, none);
  halves.update(0.25, 1.0, none);
  whole.update(0.5, 1.0, none);
  for (std::size_t j = 0; j < 3; ++j)
    EXPECT_NEAR(halves.weights()[j], whole.weights()[j], 1e-14) << j;
  whole.update(60.0, 1.0, none);
  EXPECT_NEAR(whole.weights()[1], 0.5, 1e-12);
}

// A member that could not explain a measurement is floored at 1e-12, not zero; the weights sum
// to 1.
TEST(ModelWeights, NoMemberDiesForGood) {
  ModelWeights w({1.0, 1.0});
  const std::vector<double> l = {0.0, -1e6};
  w.update(0.1, 1.0, l);
  EXPECT_NEAR(w.weights()[1] / kModelWeightFloor, 1.0, 1e-11);  // floored, renormalised
  EXPECT_NEAR(w.weights()[0] + w.weights()[1], 1.0, 1e-15);
}

TEST(ModelWeights, RejectsBadPriorsAndLengths) {
  EXPECT_THROW(ModelWeights({}), std::invalid_argument);
  EXPECT_THROW(ModelWeights({1.0, 0.0}), std::invalid_argument);
  ModelWeights w({1.0, 1.0});
  EXPECT_THROW(w.update(0.1, 1.0, std::vector<double>{0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace opf
