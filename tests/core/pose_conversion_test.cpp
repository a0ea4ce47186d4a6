#include "opf/core/pose_conversion.h"

#include "opf/core/random.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opf {
namespace {

TEST(PoseConversion, RoundTripsTranslationAndOrientation) {
  const Eigen::Vector3d p(0.4, -0.2, 1.5);
  const Eigen::Quaterniond q = so3::exp(Eigen::Vector3d(-0.3, 2.0, 0.4));
  const auto pose = make_pose(p, q);
  EXPECT_LT((translation_of(pose) - p).norm(), 1e-15);
  EXPECT_LT(so3::angle_between(orientation_of(pose), q), 1e-14);
}

TEST(PoseConversion, MatchesMrptYawPitchRoll) {
  const mrpt::poses::CPose3D mrpt_pose(0.1, 0.2, 0.3, 0.7, -0.4, 0.2);
  const auto rebuilt = make_pose(translation_of(mrpt_pose), orientation_of(mrpt_pose));
  EXPECT_NEAR(rebuilt.yaw(), 0.7, 1e-12);
  EXPECT_NEAR(rebuilt.pitch(), -0.4, 1e-12);
  EXPECT_NEAR(rebuilt.roll(), 0.2, 1e-12);
}

// The tangent covariance is mapped to yaw-pitch-roll with the Jacobian at the mean: check it
// against the sample covariance of ypr over many small perturbations (linear regime).
TEST(PoseConversion, PosePdfCovarianceMatchesSampledYawPitchRoll) {
  const Eigen::Quaterniond mean = so3::exp(Eigen::Vector3d(0.3, 0.5, -0.8));
  Eigen::Matrix3d tangent;
  tangent << 4e-6, 1e-6, 0, 1e-6, 9e-6, -2e-6, 0, -2e-6, 1e-5;
  const auto pdf =
      make_pose_pdf(Eigen::Vector3d(1, 2, 3), Eigen::Matrix3d::Identity() * 1e-4, mean, tangent);
  const Eigen::LLT<Eigen::Matrix3d> chol(tangent);
  Random random(3);
  constexpr int kN = 40000;
  Eigen::Matrix3Xd ypr(3, kN);
  for (int i = 0; i < kN; ++i) {
    const Eigen::Vector3d e =
        chol.matrixL() * Eigen::Vector3d(random.normal(), random.normal(), random.normal());
    const auto pose = make_pose({0, 0, 0}, mean * so3::exp(e));
    ypr.col(i) << pose.yaw(), pose.pitch(), pose.roll();
  }
  const Eigen::Matrix3Xd centred = ypr.colwise() - ypr.rowwise().mean();
  const Eigen::Matrix3d sample = centred * centred.transpose() / (kN - 1);
  const Eigen::Matrix3d mapped = pdf.cov.asEigen().bottomRightCorner<3, 3>();
  // Sample covariance relative error ~ sqrt(2/N) = 0.7%: allow 4% of the largest entry.
  EXPECT_LT((sample - mapped).cwiseAbs().maxCoeff(), 0.04 * mapped.cwiseAbs().maxCoeff());
  EXPECT_DOUBLE_EQ(pdf.cov(0, 0), 1e-4);
  EXPECT_DOUBLE_EQ(pdf.cov(0, 3), 0.0);
}

}  // namespace
}  // namespace opf

namespace opf {
namespace {

// The analytic Euler-rate Jacobian against central differences of MRPT's own getYawPitchRoll,
// at orientations spread over the sphere (pitch kept 0.1 rad from gimbal lock).
TEST(PoseConversion, YawPitchRollJacobianMatchesFiniteDifferences) {
  Random random(11);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Vector3d v(random.uniform() * 6 - 3, random.uniform() * 6 - 3,
                            random.uniform() * 6 - 3);
    const Eigen::Quaterniond q = so3::exp(v);
    const mrpt::poses::CPose3D pose = make_pose(Eigen::Vector3d::Zero(), q);
    if (std::abs(pose.pitch()) > 1.47) continue;
    const Eigen::Matrix3d analytic = yaw_pitch_roll_jacobian(pose);
    constexpr double kStep = 1e-6;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d delta = Eigen::Vector3d::Zero();
      delta[i] = kStep;
      double y1, p1, r1, y0, p0, r0;
      make_pose(Eigen::Vector3d::Zero(), q * so3::exp(delta)).getYawPitchRoll(y1, p1, r1);
      make_pose(Eigen::Vector3d::Zero(), q * so3::exp(-delta)).getYawPitchRoll(y0, p0, r0);
      const Eigen::Vector3d numeric(std::remainder(y1 - y0, 2 * M_PI),
                                    std::remainder(p1 - p0, 2 * M_PI),
                                    std::remainder(r1 - r0, 2 * M_PI));
      // Central differences are accurate to ~1e-9 here (rounding 1e-16 / 1e-6 step).
      EXPECT_LT((analytic.col(i) - numeric / (2 * kStep)).cwiseAbs().maxCoeff(), 1e-7)
          << "trial " << trial << " column " << i;
    }
  }
}

}  // namespace
}  // namespace opf
