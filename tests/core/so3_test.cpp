#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opf {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(So3, ExpLogRoundTripsAcrossAngles) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, -2.0, 0.5).normalized();
  for (double angle : {0.0, 1e-9, 1e-5, 0.3, 2.0, kPi - 1e-6}) {
    const Eigen::Vector3d v = axis * angle;
    EXPECT_LT((so3::log(so3::exp(v)) - v).norm(), 1e-9) << "angle " << angle;
    EXPECT_NEAR(so3::exp(v).norm(), 1.0, 1e-15);
  }
}

TEST(So3, ExpMatchesEigenAngleAxis) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.2, 0.3, -0.9).normalized();
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(1.1, axis));
  EXPECT_LT(so3::angle_between(so3::exp(axis * 1.1), expected), 1e-12);
}

// exp and log take series below a small angle: there they are the closed forms (libm's sin, cos
// and atan2) to a few ulp, from a nanoradian to just either side of the switch.
TEST(So3, SeriesForSmallAnglesAreTheClosedForms) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  for (const double angle : {1e-9, 1e-4, 0.01, 0.0999, 0.1, 0.1001, 0.3}) {
    const Eigen::Quaterniond q = so3::exp(axis * angle);
    EXPECT_NEAR(q.w(), std::cos(0.5 * angle), 4e-16) << angle;
    EXPECT_LT((q.vec() - std::sin(0.5 * angle) * axis).norm(), 4e-16 * angle) << angle;
    const Eigen::Quaterniond exact(std::cos(0.5 * angle), std::sin(0.5 * angle) * axis.x(),
                                   std::sin(0.5 * angle) * axis.y(),
                                   std::sin(0.5 * angle) * axis.z());
    const double s = exact.vec().norm();
    const Eigen::Vector3d expected = exact.vec() * (2.0 * std::atan2(s, exact.w()) / s);
    EXPECT_LT((so3::log(exact) - expected).norm(), 4e-16 * angle) << angle;
  }
}

TEST(So3, LogIgnoresQuaternionSign) {
  const Eigen::Quaterniond q = so3::exp(Eigen::Vector3d(0.4, -0.1, 0.2));
  const Eigen::Quaterniond minus_q(-q.coeffs());
  EXPECT_LT((so3::log(q) - so3::log(minus_q)).norm(), 1e-15);
}

TEST(So3, GeodesicAngleIsExactNearZeroAndPi) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.0, 0.6, 0.8);
  const Eigen::Quaterniond a = so3::exp(Eigen::Vector3d(0.3, 0.2, 0.1));
  for (double angle : {1e-8, 1e-4, 1.0, kPi - 1e-7, kPi}) {
    const Eigen::Quaterniond b = a * so3::exp(axis * angle);
    EXPECT_NEAR(so3::angle_between(a, b), angle, 1e-12 + 1e-12 * angle) << angle;
    // Sign of either quaternion does not matter.
    EXPECT_NEAR(so3::angle_between(a, Eigen::Quaterniond(-b.coeffs())), angle,
                1e-12 + 1e-12 * angle);
  }
}

TEST(So3, DifferenceIsTheBodyFrameRotationVector) {
  const Eigen::Quaterniond from = so3::exp(Eigen::Vector3d(-0.7, 0.1, 0.4));
  const Eigen::Vector3d delta(0.05, -0.2, 0.3);
  EXPECT_LT((so3::difference(from, from * so3::exp(delta)) - delta).norm(), 1e-12);
}

}  // namespace
}  // namespace opf
