#include "opf/permanence/rotation_model_bank.h"

#include "opf/core/random.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace opf {
namespace {

const Eigen::Vector3d kAxis = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();

// An orientation turning at `rate` rad/s about a tilted axis, measured at 30 Hz with 0.01 rad of
// tangent noise for 3 s.
RotationModelBank measured(double rate, std::uint64_t seed) {
  Random random(seed);
  RotationModelBankOptions options;
  options.observation_noise = 0.01;
  RotationModelBank bank(options);
  for (int k = 0; k < 90; ++k) {
    const double t = k / 30.0;
    const Eigen::Vector3d e(random.normal(), random.normal(), random.normal());
    bank.update(t, so3::exp(rate * t * kAxis) * so3::exp(0.01 * e));
  }
  return bank;
}

// Fifteen members: constant orientation at 0.003, 0.03, 0.3 rad/s/sqrt(Hz), constant angular
// velocity at 0.1, 1, 10 rad/s^2/sqrt(Hz), damped angular velocity at those densities times
// T = 0.3, 1, 3 s; each model a third of the prior.
TEST(RotationModelBank, MembersAreTheStatedGrid) {
  const RotationModelBank bank;
  ASSERT_EQ(bank.members().size(), 15u);
  const std::vector<double> q = {0.003, 0.03, 0.3, 0.1, 1.0, 10.0};
  for (std::size_t j = 0; j < 6; ++j) {
    EXPECT_NEAR(bank.members()[j].intensity(), q[j], 1e-15) << j;
    EXPECT_EQ(bank.members()[j].model(), j < 3 ? RotationModel::kConstantOrientation
                                               : RotationModel::kConstantAngularVelocity);
  }
  const std::vector<double> time_constants = {0.3, 1.0, 3.0};
  for (std::size_t j = 6; j < 15; ++j) {
    const TangentRotationFilter& member = bank.members()[j];
    EXPECT_EQ(member.model(), RotationModel::kDampedAngularVelocity) << j;
    EXPECT_NEAR(member.intensity(), q[3 + (j - 6) / 3], 1e-15) << j;
    EXPECT_EQ(member.time_constant(), time_constants[(j - 6) % 3]) << j;
  }
  for (const RotationModel model :
       {RotationModel::kConstantOrientation, RotationModel::kConstantAngularVelocity,
        RotationModel::kDampedAngularVelocity})
    EXPECT_NEAR(bank.model_weight(model), 1.0 / 3.0, 1e-12);
}

// A spin at 2 rad/s: the two models of a turning body hold nearly all the weight; a still object:
// constant orientation holds most of it (on 5 seeds each).
TEST(RotationModelBank, TheModelThatDrewTheDataWins) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const RotationModelBank spinning = measured(2.0, seed);
    EXPECT_GT(spinning.model_weight(RotationModel::kConstantAngularVelocity) +
                  spinning.model_weight(RotationModel::kDampedAngularVelocity),
              0.99)
        << seed;
    EXPECT_GT(measured(0.0, seed).model_weight(RotationModel::kConstantOrientation), 0.5) << seed;
  }
}

// Flicks of a wrist: every 0.5 s the body rate jumps to 3 rad/s about a new axis and dies away
// with a time constant of 0.3 s. Damped angular velocity, the model that drew the data, holds most
// of the weight at the end (5 seeds).
TEST(RotationModelBank, FlicksThatDieAwayAreDampedAngularVelocity) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    Random random(seed);
    RotationModelBankOptions options;
    options.observation_noise = 0.01;
    RotationModelBank bank(options);
    Eigen::Quaterniond truth = Eigen::Quaterniond::Identity();
    Eigen::Vector3d rate = Eigen::Vector3d::Zero();
    const double dt = 1.0 / 30.0, decay = std::exp(-dt / 0.3);
    for (int k = 0; k < 150; ++k) {
      if (k % 15 == 0) {
        const Eigen::Vector3d axis(random.normal(), random.normal(), random.normal());
        rate = 3.0 * axis.normalized();
      }
      const Eigen::Vector3d e(random.normal(), random.normal(), random.normal());
      bank.update(k * dt, truth * so3::exp(0.01 * e));
      truth = truth * so3::exp(rate * 0.3 * (1.0 - decay));  // the exact turn over dt
      rate *= decay;
    }
    EXPECT_GT(bank.model_weight(RotationModel::kDampedAngularVelocity), 0.5) << seed;
  }
}

// The spin's mixture: every member's prediction 0.5 s ahead is listed with its weight; the
// winning members predict the turn to within 0.03 rad.
TEST(RotationModelBank, PredictListsEveryMember) {
  const RotationModelBank bank = measured(2.0, 7);
  const auto prediction = bank.predict(0.5);
  ASSERT_EQ(prediction.size(), 15u);
  double sum = 0.0;
  for (std::size_t j = 0; j < prediction.size(); ++j) {
    sum += prediction[j].weight;
    EXPECT_EQ(prediction[j].weight, bank.weights()[j]);
    if (prediction[j].weight > 0.1) {
      EXPECT_LT(
          so3::angle_between(prediction[j].orientation, so3::exp(2.0 * (89 / 30.0 + 0.5) * kAxis)),
          0.03)
          << j;
    }
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
  const std::size_t chosen = bank.sample_member(0.5);
  EXPECT_EQ(bank.members()[chosen].model(), RotationModel::kConstantAngularVelocity);
}

// On a camera's clock (every interval 1/30 s +- 1 ms) each member steps by its own model: the
// bank computes its members' steps together, and each member's prediction over the last interval
// (that step) is its own model's, to within what 2 ns more of horizon moves it.
TEST(RotationModelBank, OnAJitteredClockEveryMemberStepsByItsOwnModel) {
  Random random(6);
  RotationModelBank bank;
  double t = 0.0, dt = 0.0;
  for (int k = 0; k < 60; ++k) {
    const double next = t + 1.0 / 30.0 + 0.002 * (random.uniform() - 0.5);
    dt = next - t;  // the interval the bank takes
    t = next;
    bank.update(t, so3::exp(2.0 * t * kAxis));
  }
  const auto shared = bank.predict(dt);
  for (std::size_t j = 0; j < shared.size(); ++j) {
    const RotationMemberPrediction own = bank.member_prediction(j, dt + 2e-9);
    EXPECT_LT(so3::angle_between(shared[j].orientation, own.orientation), 1e-8) << j;
    EXPECT_TRUE(shared[j].covariance.isApprox(own.covariance, 1e-6)) << j;
  }
}

// A 10 s gap and a flipped (pi rad) outlier leave every weight and prediction finite.
TEST(RotationModelBank, GapsAndOutliersLeaveEverythingFinite) {
  RotationModelBank bank = measured(1.0, 3);
  bank.update(13.0, so3::exp(13.0 * kAxis));
  bank.update(13.0 + 1.0 / 30.0, so3::exp(13.0 * kAxis) * so3::exp(3.1 * Eigen::Vector3d::UnitX()));
  double sum = 0.0;
  for (const RotationMemberPrediction& p : bank.predict(1.0)) {
    sum += p.weight;
    EXPECT_TRUE(std::isfinite(p.weight) && p.orientation.coeffs().allFinite() &&
                p.covariance.allFinite());
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
}

// A still object turned by 1 rad in one frame (put down another way) and still again: the
// members lose it at once, restart from the second orientation past their gate, and within 2 s
// constant orientation holds most of the weight again, every member predicting the new pose to
// within 0.03 rad. Without the restart its Student-t likelihood would read the new pose as an
// outlier for good.
TEST(RotationModelBank, MembersThatLostTheObjectRestart) {
  RotationModelBank bank = measured(0.0, 5);
  Random random(6);
  const Eigen::Quaterniond turned = so3::exp(1.0 * kAxis);
  for (int k = 90; k < 150; ++k) {
    const Eigen::Vector3d e(random.normal(), random.normal(), random.normal());
    bank.update(k / 30.0, turned * so3::exp(0.01 * e));
  }
  EXPECT_GT(bank.model_weight(RotationModel::kConstantOrientation), 0.5);
  for (const RotationMemberPrediction& p : bank.predict(0.0))
    EXPECT_LT(so3::angle_between(p.orientation, turned), 0.03);
}

TEST(RotationModelBank, ABadOptionThrowsNamingIt) {
  RotationModelBankOptions options;
  options.observation_noise = 0.0;
  try {
    RotationModelBank bank(options);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "rotation model bank option observation_noise must be a positive number (rad)"),
              std::string::npos)
        << e.what();
  }
  options = {};
  options.memory = -1.0;
  EXPECT_THROW(RotationModelBank{options}, std::invalid_argument);
  RotationModelBank bank;
  EXPECT_THROW(bank.predict(0.1), std::logic_error);
}

// The bank's growth per tangent axis is its members' growths in trace, weighted, over three.
TEST(RotationModelBank, VarianceGrowthIsTheMembersWeightedPerAxis) {
  const RotationModelBank bank = measured(1.5, 4);
  double expected = 0.0;
  for (std::size_t k = 0; k < bank.members().size(); ++k)
    expected += bank.weights()[k] * bank.members()[k].orientation_variance_growth(0.2);
  EXPECT_NEAR(bank.variance_growth(0.2), expected / 3.0, 1e-15);
  EXPECT_GT(bank.variance_growth(0.2), bank.variance_growth(1.0 / 30.0));
}

}  // namespace
}  // namespace opf
