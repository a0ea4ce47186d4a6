#include "opf/core/calibration.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/random.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

#include <cmath>
#include <limits>

namespace opf {
namespace {

// A correlated, anisotropic 3x3 covariance (m^2 or rad^2): std 1-4 cm, correlations up to 0.5.
Eigen::Matrix3d example_covariance() {
  Eigen::Matrix3d a;
  a << 0.02, 0.0, 0.0,  //
      0.01, 0.03, 0.0,  //
      -0.01, 0.02, 0.04;
  return a * a.transpose();
}

Estimate estimate_with(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                       const Eigen::Matrix3d& position_covariance,
                       const Eigen::Matrix3d& tangent_covariance) {
  Estimate e;
  e.pose = make_pose_pdf(position, position_covariance, orientation, tangent_covariance);
  return e;
}

struct Calibration {
  double mean_over_dimension = 0.0;
  double inside95 = 0.0;
};

// Truths drawn around a fixed estimate from N(0, drawn_covariance) in position and in the body
// tangent space, scored against the estimate's reported covariance.
Calibration draw(const Eigen::Matrix3d& reported, const Eigen::Matrix3d& drawn, bool rotation) {
  constexpr int kDraws = 20000;
  const Eigen::Vector3d position(1.0, -2.0, 0.5);
  const Eigen::Quaterniond orientation = so3::exp(Eigen::Vector3d(0.3, -0.4, 1.1));
  const Estimate estimate = estimate_with(position, orientation, reported, reported);
  const Eigen::Matrix3d factor = drawn.llt().matrixL();
  Random random(20261127);
  Calibration c;
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::Vector3d z(random.normal(), random.normal(), random.normal());
    const Eigen::Vector3d error = factor * z;
    // The truth is where the estimate's error e = truth - estimate puts it.
    const mrpt::poses::CPose3D truth = rotation ? make_pose(position, orientation * so3::exp(error))
                                                : make_pose(position + error, orientation);
    const double nees =
        rotation ? rotation_nees(estimate, truth) : translation_nees(estimate, truth);
    c.mean_over_dimension += nees / 3.0 / kDraws;
    c.inside95 += (nees <= kChiSquare3Dof95 ? 1.0 : 0.0) / kDraws;
  }
  return c;
}

// Over 20000 draws the mean NEES / 3 has std sqrt(2/3/20000) = 0.0058 and the share inside the
// 95% ellipsoid std 0.0015: 3% and 0.006 are over 4 standard deviations.
TEST(Calibration, GaussianErrorsWithTheReportedCovarianceAreCalibrated) {
  const Calibration t = draw(example_covariance(), example_covariance(), false);
  EXPECT_NEAR(t.mean_over_dimension, 1.0, 0.03);
  EXPECT_NEAR(t.inside95, 0.95, 0.006);
  const Calibration r = draw(example_covariance(), example_covariance(), true);
  EXPECT_NEAR(r.mean_over_dimension, 1.0, 0.03);
  EXPECT_NEAR(r.inside95, 0.95, 0.006);
}

TEST(Calibration, ACovarianceThreeTimesTooWideInStdGivesANinth) {
  const Eigen::Matrix3d drawn = example_covariance();
  const Calibration t = draw(9.0 * drawn, drawn, false);
  EXPECT_NEAR(t.mean_over_dimension, 1.0 / 9.0, 0.03 / 9.0);
  EXPECT_GT(t.inside95, 0.999);  // chi2_3 > 9 x 7.81 has probability ~1e-13
  const Calibration r = draw(9.0 * drawn, drawn, true);
  EXPECT_NEAR(r.mean_over_dimension, 1.0 / 9.0, 0.03 / 9.0);
}

TEST(Calibration, AnOverconfidentCovarianceScoresAboveOne) {
  const Calibration t = draw(example_covariance() / 4.0, example_covariance(), false);
  EXPECT_NEAR(t.mean_over_dimension, 4.0, 0.12);
  EXPECT_LT(t.inside95, 0.6);  // P(chi2_3 <= 7.81 / 4) = 0.42
}

TEST(Calibration, KnownValueOfADiagonalCovariance) {
  const Eigen::Matrix3d covariance = Eigen::Vector3d(0.01, 0.04, 0.09).asDiagonal();
  const Estimate e = estimate_with(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity(),
                                   covariance, covariance);
  // e = (0.1, 0.2, 0.3): 1 + 1 + 1.
  EXPECT_NEAR(translation_nees(e, make_pose({0.1, 0.2, 0.3}, Eigen::Quaterniond::Identity())), 3.0,
              1e-12);
  // A rotation of 0.3 rad about the body z axis against a z variance of 0.09: 1.
  const auto turned = make_pose(Eigen::Vector3d::Zero(), so3::exp(Eigen::Vector3d(0, 0, 0.3)));
  EXPECT_NEAR(rotation_nees(e, turned), 1.0, 1e-9);
}

TEST(Calibration, ASingularCovarianceIsInfinitelyOverconfident) {
  const Estimate e = estimate_with(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity(),
                                   Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero());
  const auto truth = make_pose({0.1, 0, 0}, so3::exp(Eigen::Vector3d(0, 0, 0.1)));
  EXPECT_EQ(translation_nees(e, truth), std::numeric_limits<double>::infinity());
  EXPECT_EQ(rotation_nees(e, truth), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace opf
