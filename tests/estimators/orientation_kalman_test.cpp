#include "opf/estimators/orientation_kalman.h"

#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opf {
namespace {

const Eigen::Quaterniond kStart = so3::exp(Eigen::Vector3d(0.3, -0.2, 0.9));

TEST(OrientationKalman, StartsAtTheOrientationWithTheGivenStds) {
  OrientationKalman filter;
  filter.initialise(kStart, 0.05, 1.0);
  EXPECT_TRUE(filter.orientation().isApprox(kStart, 1e-15));
  EXPECT_EQ(filter.angular_velocity(), Eigen::Vector3d::Zero());
  kalman::Matrix<6> expected = kalman::Matrix<6>::Zero();
  expected.diagonal() << 0.05 * 0.05, 0.05 * 0.05, 0.05 * 0.05, 1.0, 1.0, 1.0;
  EXPECT_EQ(filter.covariance(), expected);
}

TEST(OrientationKalman, APredictionAtRestAddsTheProcessNoiseThroughTheTransition) {
  // At zero rate the transition is [I dt I; 0 I]: P(0,0) grows by dt^2 sigma_w^2 + q^2 dt^3 / 3.
  OrientationKalman filter;
  filter.initialise(kStart, 0.05, 1.0);
  const double dt = 0.1, q = 2.0;
  filter.predict(dt, q);
  EXPECT_TRUE(filter.orientation().isApprox(kStart, 1e-15));
  EXPECT_NEAR(filter.covariance()(0, 0), 0.0025 + dt * dt * 1.0 + q * q * dt * dt * dt / 3.0,
              1e-15);
  EXPECT_NEAR(filter.covariance()(0, 3), dt * 1.0 + q * q * dt * dt / 2.0, 1e-15);
  EXPECT_NEAR(filter.covariance()(3, 3), 1.0 + q * q * dt, 1e-15);
}

TEST(OrientationKalman, AnUpdateMovesAlongTheResidualByTheScalarGainAndIgnoresTheSign) {
  // From diag(s^2, ...) with measurement variance r the orientation moves by s^2 / (s^2 + r) of
  // the tangent-space residual, about one axis.
  const Eigen::Vector3d residual(0.0, 0.0, 0.04);
  const Eigen::Quaterniond measured = kStart * so3::exp(residual);
  for (const double sign : {1.0, -1.0}) {
    OrientationKalman filter;
    filter.initialise(kStart, 0.05, 1.0);
    filter.update(Eigen::Quaterniond(sign * measured.coeffs()), 0.0025);
    const Eigen::Vector3d moved = so3::difference(kStart, filter.orientation());
    EXPECT_NEAR(moved.z(), 0.5 * residual.z(), 1e-12) << sign;
    EXPECT_NEAR(moved.head<2>().norm(), 0.0, 1e-12) << sign;
    EXPECT_NEAR(filter.covariance()(2, 2), 0.5 * 0.0025, 1e-15) << sign;
    EXPECT_NEAR(filter.covariance()(0, 0), 0.5 * 0.0025, 1e-15) << sign;
  }
}

}  // namespace
}  // namespace opf
