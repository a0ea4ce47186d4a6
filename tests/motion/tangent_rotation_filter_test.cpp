#include "opf/motion/tangent_rotation_filter.h"

#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/motion/damped_velocity_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opf {
namespace {

const Eigen::Vector3d kAxis = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();

// A spin at 2 rad/s about a fixed tilted axis, measured at 30 Hz with 0.01 rad of tangent noise
// for 2 s: constant angular velocity learns the body rate (= 2 axis for a fixed axis) to within
// 0.1 rad/s (its white angular acceleration of 1 rad/s^2/sqrt(Hz) keeps the rate loose: about
// 0.05 rad/s std per axis after 2 s) and predicts 0.5 s ahead to within 0.06 rad.
TEST(TangentRotationFilter, ConstantAngularVelocityFollowsASpin) {
  Random random(4);
  TangentRotationFilter filter(RotationModel::kConstantAngularVelocity, 1.0);
  filter.initialise(Eigen::Quaterniond::Identity(), 0.01, 1.0);
  for (int k = 1; k <= 60; ++k) {
    const double t = k / 30.0;
    const Eigen::Vector3d e(random.normal(), random.normal(), random.normal());
    filter.predict(1.0 / 30.0);
    filter.update(so3::exp(2.0 * t * kAxis) * so3::exp(0.01 * e), 1e-4);
  }
  EXPECT_LT((filter.angular_velocity() - 2.0 * kAxis).norm(), 0.1) << filter.angular_velocity();
  const auto ahead = filter.predicted(0.5);
  EXPECT_LT(so3::angle_between(ahead.orientation, so3::exp(5.0 * kAxis)), 0.06);
  EXPECT_GT(ahead.covariance.trace(), 0.0);
}

// Constant orientation pins the rate at 0 and adds q^2 h per tangent axis over h.
TEST(TangentRotationFilter, ConstantOrientationIsARandomWalk) {
  TangentRotationFilter filter(RotationModel::kConstantOrientation, 0.2);
  const Eigen::Quaterniond start = so3::exp(Eigen::Vector3d(0.1, 0.2, -0.3));
  filter.initialise(start, 0.05, 1.0);
  const auto ahead = filter.predicted(2.0);
  EXPECT_LT(so3::angle_between(ahead.orientation, start), 1e-15);
  EXPECT_TRUE(ahead.covariance.isApprox((0.0025 + 0.04 * 2.0) * Eigen::Matrix3d::Identity(), 1e-14))
      << ahead.covariance;
  filter.predict(0.1);
  filter.update(start * so3::exp(Eigen::Vector3d(0.02, 0.0, 0.0)), 0.01);
  EXPECT_EQ(filter.angular_velocity(), Eigen::Vector3d::Zero());
}

// One step by hand, per tangent axis (at rate 0 the error transport is the identity): from
// P = diag(0.01, 1), predict 0.1 s at q = 1: P_tt = 0.01 + 0.01 + 1/3000, P_tw = 0.1 + 0.005,
// P_ww = 1.1; measuring a turn r = 0.02 rad about x with variance 0.0004 corrects the rate by
// P_tw / (P_tt + 0.0004) r.
TEST(TangentRotationFilter, OneStepMatchesTheHandComputedGain) {
  TangentRotationFilter filter(RotationModel::kConstantAngularVelocity, 1.0);
  filter.initialise(Eigen::Quaterniond::Identity(), 0.1, 1.0);
  filter.predict(0.1);
  filter.update(so3::exp(Eigen::Vector3d(0.02, 0.0, 0.0)), 0.0004);
  const double p_tt = 0.02 + 1.0 / 3000.0, p_tw = 0.105;
  EXPECT_NEAR(filter.angular_velocity().x(), p_tw / (p_tt + 0.0004) * 0.02, 1e-12);
  EXPECT_NEAR(so3::log(filter.orientation()).x(), p_tt / (p_tt + 0.0004) * 0.02, 1e-12);
  EXPECT_NEAR(filter.angular_velocity().tail<2>().norm(), 0.0, 1e-15);
}

// The first update's log-likelihood is log N(r; 0, S), S = (sigma_0^2 + var) I, r the tangent
// difference, and its squared distance r^T S^-1 r: here r = (0.03, 0, 0), S = 0.02 I.
TEST(TangentRotationFilter, UpdateReturnsTheInnovationsDistanceAndLogLikelihood) {
  TangentRotationFilter filter(RotationModel::kConstantAngularVelocity, 1.0);
  filter.initialise(Eigen::Quaterniond::Identity(), 0.1, 1.0);
  const auto update = filter.update(so3::exp(Eigen::Vector3d(0.03, 0.0, 0.0)), 0.01);
  const double expected =
      -0.5 * (0.03 * 0.03 / 0.02 + 3.0 * std::log(0.02) + 3.0 * std::log(2.0 * std::numbers::pi));
  EXPECT_NEAR(update.log_likelihood, expected, 1e-12);
  EXPECT_NEAR(update.squared_distance, 0.03 * 0.03 / 0.02, 1e-12);
  EXPECT_EQ(rotation_model_name(RotationModel::kConstantOrientation), "constant_orientation");
  EXPECT_EQ(rotation_model_name(RotationModel::kConstantAngularVelocity),
            "constant_angular_velocity");
}

// The Kalman baselines' orientation filter (cvkf, imm): constant angular velocity.
const Eigen::Quaterniond kStart = so3::exp(Eigen::Vector3d(0.3, -0.2, 0.9));

TEST(TangentRotationFilter, ConstantAngularVelocityStartsWithTheGivenStds) {
  TangentRotationFilter filter(RotationModel::kConstantAngularVelocity, 1.0);
  filter.initialise(kStart, 0.05, 1.0);
  EXPECT_TRUE(filter.orientation().isApprox(kStart, 1e-15));
  EXPECT_EQ(filter.angular_velocity(), Eigen::Vector3d::Zero());
  kalman::Matrix<6> expected = kalman::Matrix<6>::Zero();
  expected.diagonal() << 0.05 * 0.05, 0.05 * 0.05, 0.05 * 0.05, 1.0, 1.0, 1.0;
  EXPECT_EQ(filter.covariance(), expected);
}

TEST(TangentRotationFilter, AtRestAPredictionAddsTheProcessNoiseThroughTheTransition) {
  // At zero rate the transition is [I dt I; 0 I]: P(0,0) grows by dt^2 sigma_w^2 + q^2 dt^3 / 3.
  const double dt = 0.1, q = 2.0;
  TangentRotationFilter filter(RotationModel::kConstantAngularVelocity, q);
  filter.initialise(kStart, 0.05, 1.0);
  filter.predict(dt);
  EXPECT_TRUE(filter.orientation().isApprox(kStart, 1e-15));
  EXPECT_NEAR(filter.covariance()(0, 0), 0.0025 + dt * dt * 1.0 + q * q * dt * dt * dt / 3.0,
              1e-15);
  EXPECT_NEAR(filter.covariance()(0, 3), dt * 1.0 + q * q * dt * dt / 2.0, 1e-15);
  EXPECT_NEAR(filter.covariance()(3, 3), 1.0 + q * q * dt, 1e-15);
}

TEST(TangentRotationFilter, AnUpdateMovesAlongTheResidualByTheScalarGainAndIgnoresTheSign) {
  // From diag(s^2, ...) with measurement variance r the orientation moves by s^2 / (s^2 + r) of
  // the tangent-space residual, about one axis.
  const Eigen::Vector3d residual(0.0, 0.0, 0.04);
  const Eigen::Quaterniond measured = kStart * so3::exp(residual);
  for (const double sign : {1.0, -1.0}) {
    TangentRotationFilter filter(RotationModel::kConstantAngularVelocity, 1.0);
    filter.initialise(kStart, 0.05, 1.0);
    filter.update(Eigen::Quaterniond(sign * measured.coeffs()), 0.0025);
    const Eigen::Vector3d moved = so3::difference(kStart, filter.orientation());
    EXPECT_NEAR(moved.z(), 0.5 * residual.z(), 1e-12) << sign;
    EXPECT_NEAR(moved.head<2>().norm(), 0.0, 1e-12) << sign;
    EXPECT_NEAR(filter.covariance()(2, 2), 0.5 * 0.0025, 1e-15) << sign;
    EXPECT_NEAR(filter.covariance()(0, 0), 0.5 * 0.0025, 1e-15) << sign;
  }
}

// Damped angular velocity forgets its rate: from w0 about a fixed axis, h s ahead the body has
// turned by w0 T (1 - exp(-h / T)) and the rate is w0 exp(-h / T), in one step or in ten.
TEST(TangentRotationFilter, DampedAngularVelocityForgetsItsRate) {
  const double time_constant = 0.5, h = 0.8;
  const Eigen::Vector3d rate = 2.0 * kAxis;
  TangentRotationFilter once(RotationModel::kDampedAngularVelocity, 1.0, time_constant);
  once.initialise(kStart, 0.05, 1.0, rate);
  TangentRotationFilter stepped = once;
  once.predict(h);
  for (int k = 0; k < 10; ++k) stepped.predict(h / 10.0);
  const double decay = std::exp(-h / time_constant);
  const Eigen::Quaterniond expected = kStart * so3::exp(rate * time_constant * (1.0 - decay));
  EXPECT_LT(so3::angle_between(once.orientation(), expected), 1e-14);
  EXPECT_LT(so3::angle_between(stepped.orientation(), expected), 1e-13);
  EXPECT_LT((once.angular_velocity() - decay * rate).norm(), 1e-15);
  EXPECT_LT((stepped.angular_velocity() - decay * rate).norm(), 1e-14);
  EXPECT_THROW(TangentRotationFilter(RotationModel::kDampedAngularVelocity, 1.0, 0.0),
               std::invalid_argument);
  EXPECT_EQ(rotation_model_name(RotationModel::kDampedAngularVelocity), "damped_angular_velocity");
}

// A step is reused while the interval repeats and made afresh when it changes: after 0.1, 0.1,
// 0.35 and 0.1 s the rate has decayed by exp(-0.65 / T) and the body turned by w0 T (1 - that), as
// in one step of 0.65 s; a stale 0.1 s step in place of the 0.35 s one would leave exp(-0.4 / T).
TEST(TangentRotationFilter, ARepeatedIntervalReusesItsStepAndANewOneDoesNot) {
  const double time_constant = 0.5;
  const Eigen::Vector3d rate = 2.0 * kAxis;
  TangentRotationFilter stepped(RotationModel::kDampedAngularVelocity, 1.0, time_constant);
  stepped.initialise(kStart, 0.05, 1.0, rate);
  for (const double dt : {0.1, 0.1, 0.35, 0.1}) stepped.predict(dt);
  const double decay = std::exp(-0.65 / time_constant);
  const Eigen::Quaterniond expected = kStart * so3::exp(rate * time_constant * (1.0 - decay));
  EXPECT_LT((stepped.angular_velocity() - decay * rate).norm(), 1e-14);
  EXPECT_LT(so3::angle_between(stepped.orientation(), expected), 1e-13);
}

// A step given by the caller (a bank computes its members' steps together) is axis_model()'s, so
// the filter steps and predicts as by its own, to the bit.
TEST(TangentRotationFilter, AStepGivenIsItsAxisModelsOwn) {
  for (const RotationModel model :
       {RotationModel::kConstantOrientation, RotationModel::kConstantAngularVelocity,
        RotationModel::kDampedAngularVelocity}) {
    TangentRotationFilter own(model, 1.0, 0.3), given(model, 1.0, 0.3);
    for (TangentRotationFilter* f : {&own, &given}) f->initialise(kStart, 0.05, 1.0, kAxis);
    for (const double dt : {0.1, 0.1, 0.0337}) {
      own.predict(dt);
      given.predict(dt, given.axis_model().step(dt));
    }
    EXPECT_EQ(own.covariance(), given.covariance());
    EXPECT_EQ(own.orientation().coeffs(), given.orientation().coeffs());
    const auto a = own.predicted(0.4), b = given.predicted(0.4, given.axis_model().step(0.4));
    EXPECT_EQ(a.covariance, b.covariance);
    EXPECT_EQ(a.orientation.coeffs(), b.orientation.coeffs());
  }
}

// At rate zero every tangent axis steps by damped velocity's F and Q (damped_velocity_motion.h):
// from P = diag(0.0025, 1) per axis, P <- F P F^T + Q.
TEST(TangentRotationFilter, DampedAngularVelocityStepsEachAxisByTheDampedModel) {
  const double q = 2.0, time_constant = 0.3, dt = 0.1;
  TangentRotationFilter filter(RotationModel::kDampedAngularVelocity, q, time_constant);
  filter.initialise(kStart, 0.05, 1.0);
  filter.predict(dt);
  const AxisMotionStep axis = damped_velocity_motion(q, time_constant, dt);
  Eigen::Matrix2d p0;
  p0 << 0.0025, 0.0, 0.0, 1.0;
  const Eigen::Matrix2d expected =
      axis.transition * p0 * axis.transition.transpose() + axis.process_noise;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(filter.covariance()(i, i), expected(0, 0), 1e-15) << i;
    EXPECT_NEAR(filter.covariance()(i, i + 3), expected(0, 1), 1e-15) << i;
    EXPECT_NEAR(filter.covariance()(i + 3, i + 3), expected(1, 1), 1e-15) << i;
  }
  EXPECT_NEAR(filter.covariance()(0, 1), 0.0, 1e-15);
}

// With T far beyond the horizon the damped model is constant angular velocity.
TEST(TangentRotationFilter, DampedAngularVelocityWithALongTimeConstantIsConstantRate) {
  TangentRotationFilter damped(RotationModel::kDampedAngularVelocity, 1.0, 1e6);
  TangentRotationFilter constant(RotationModel::kConstantAngularVelocity, 1.0);
  for (TangentRotationFilter* f : {&damped, &constant}) f->initialise(kStart, 0.05, 1.0, kAxis);
  const auto a = damped.predicted(0.5), b = constant.predicted(0.5);
  EXPECT_LT(so3::angle_between(a.orientation, b.orientation), 1e-6);
  EXPECT_TRUE(a.covariance.isApprox(b.covariance, 1e-5)) << a.covariance << "\n" << b.covariance;
}

// The filter's update, formed by blocks for H = [I 0], is the Kalman core's general update
// (Joseph form, linear_kalman.h) to rounding: after a turn with a correlated covariance, with
// Gaussian and with Student-t noise.
TEST(TangentRotationFilter, TheBlockUpdateIsTheGeneralKalmanUpdate) {
  for (const bool heavy : {false, true}) {
    TangentRotationFilter filter(RotationModel::kDampedAngularVelocity, 1.0, 1.0);
    filter.initialise(kStart, 0.05, 1.0, 2.0 * kAxis);
    filter.predict(0.2);
    const Eigen::Quaterniond measured =
        filter.orientation() * so3::exp(Eigen::Vector3d(0.03, -0.02, 0.05));
    kalman::Matrix<6> covariance = filter.covariance();
    kalman::Matrix<3, 6> h = kalman::Matrix<3, 6>::Zero();
    h.leftCols<3>().setIdentity();
    const Eigen::Matrix3d noise = 0.0004 * Eigen::Matrix3d::Identity();
    const Eigen::Vector3d residual = so3::difference(filter.orientation(), measured);
    const kalman::StudentTNoise t = kalman::student_t_noise<3>(1.0);
    const auto general =
        heavy ? kalman::update_covariance_student_t<6, 3>(covariance, h, noise, residual, t)
              : kalman::update_covariance<6, 3>(covariance, h, noise, residual);
    const auto block = heavy ? filter.update(measured, 0.0004, t) : filter.update(measured, 0.0004);
    EXPECT_TRUE(filter.covariance().isApprox(covariance, 1e-12)) << heavy;
    EXPECT_TRUE(block.correction.isApprox(general.correction, 1e-12)) << heavy;
    EXPECT_NEAR(block.squared_distance, general.squared_distance, 1e-12) << heavy;
    EXPECT_NEAR(block.determinant, general.determinant, 1e-12 * general.determinant) << heavy;
    if (!heavy) {
      EXPECT_NEAR(block.log_likelihood, general.log_likelihood, 1e-12);
    }
  }
}

// The closed form of the orientation's variance growth is the trace a prediction gives, for every
// model, at the interval last stepped (its step reused) and at another.
TEST(TangentRotationFilter, OrientationVarianceGrowthIsThePredictionsTrace) {
  for (const auto& [model, time_constant] :
       {std::pair{RotationModel::kConstantOrientation, 0.0},
        std::pair{RotationModel::kConstantAngularVelocity, 0.0},
        std::pair{RotationModel::kDampedAngularVelocity, 0.5}}) {
    TangentRotationFilter filter(model, 1.0, time_constant);
    filter.initialise(kStart, 0.05, 1.0, 2.0 * kAxis);
    filter.predict(0.1);
    filter.update(kStart * so3::exp(0.2 * kAxis), 0.01 * 0.01);
    for (const double horizon : {0.1, 0.7}) {
      const double expected = filter.predicted(horizon).covariance.trace() -
                              filter.covariance().topLeftCorner<3, 3>().trace();
      EXPECT_NEAR(filter.orientation_variance_growth(horizon), expected, 1e-12 * expected)
          << rotation_model_name(model) << " at " << horizon << " s";
      EXPECT_GT(expected, 0.0);
    }
  }
}

}  // namespace
}  // namespace opf
