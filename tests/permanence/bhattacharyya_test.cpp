#include "opf/permanence/bhattacharyya.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opf {
namespace {

TEST(Bhattacharyya, IdenticalGaussiansAreAtZeroDistance) {
  Eigen::Matrix3d s;
  s << 2e-4, 1e-5, 0, 1e-5, 1e-4, 0, 0, 0, 3e-4;
  const Eigen::Vector3d m(0.4, 0.1, 0.0);
  EXPECT_NEAR(bhattacharyya_distance(m, s, m, s), 0.0, 1e-9);
}

TEST(Bhattacharyya, EqualCovariancesGiveAnEighthOfTheMahalanobisDistance) {
  // No square root on the Mahalanobis term: D_B = dmu^2 / (8 sigma^2) for equal 1-D Gaussians.
  const Eigen::VectorXd a = Eigen::VectorXd::Constant(1, 0.0);
  const Eigen::VectorXd b = Eigen::VectorXd::Constant(1, 0.3);
  const Eigen::MatrixXd s = Eigen::MatrixXd::Constant(1, 1, 0.01);
  EXPECT_NEAR(bhattacharyya_distance(a, s, b, s, 0.0), 0.09 / 0.08, 1e-12);
}

TEST(Bhattacharyya, MatchesTheClosedFormForDifferentVariances) {
  // 1-D: D_B = (mu1-mu2)^2 / (4 (s1+s2)) + 1/2 ln((s1+s2) / (2 sqrt(s1 s2))).
  const double s1 = 0.01, s2 = 0.04, d = 0.2;
  const double expected =
      d * d / (4 * (s1 + s2)) + 0.5 * std::log((s1 + s2) / (2 * std::sqrt(s1 * s2)));
  EXPECT_NEAR(bhattacharyya_distance(
                  Eigen::VectorXd::Constant(1, 0.0), Eigen::MatrixXd::Constant(1, 1, s1),
                  Eigen::VectorXd::Constant(1, d), Eigen::MatrixXd::Constant(1, 1, s2), 0.0),
              expected, 1e-12);
}

TEST(Bhattacharyya, SingularCovarianceIsRegularised) {
  const Eigen::Vector2d a(0, 0), b(0.1, 0);
  const Eigen::Matrix2d collapsed = Eigen::Matrix2d::Zero();
  const double d = bhattacharyya_distance(a, collapsed, b, Eigen::Matrix2d::Identity() * 1e-4);
  EXPECT_TRUE(std::isfinite(d));
  EXPECT_GT(d, 0.0);
}

TEST(Bhattacharyya, RejectsMismatchedDimensions) {
  EXPECT_THROW(bhattacharyya_distance(Eigen::Vector2d::Zero(), Eigen::Matrix2d::Identity(),
                                      Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity()),
               std::invalid_argument);
}

}  // namespace
}  // namespace opf
