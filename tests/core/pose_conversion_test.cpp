#include "core/pose_conversion.h"

#include "core/so3.h"
#include "particles/random.h"

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
