#include "core/pose_conversion.h"

#include "core/so3.h"

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/CQuaternion.h>

#include <cmath>
#include <numbers>

namespace opf {

Eigen::Vector3d translation_of(const mrpt::poses::CPose3D& pose) {
  return {pose.x(), pose.y(), pose.z()};
}

Eigen::Quaterniond orientation_of(const mrpt::poses::CPose3D& pose) {
  const Eigen::Matrix3d rotation = pose.getRotationMatrix().asEigen();
  return Eigen::Quaterniond(rotation).normalized();
}

mrpt::poses::CPose3D make_pose(const Eigen::Vector3d& translation,
                               const Eigen::Quaterniond& orientation) {
  const Eigen::Matrix3d rotation = orientation.normalized().toRotationMatrix();
  return mrpt::poses::CPose3D(mrpt::math::CMatrixDouble33(rotation),
                              mrpt::math::CVectorFixedDouble<3>(translation));
}

namespace {

Eigen::Vector3d yaw_pitch_roll(const Eigen::Quaterniond& q) {
  double yaw = 0, pitch = 0, roll = 0;
  make_pose(Eigen::Vector3d::Zero(), q).getYawPitchRoll(yaw, pitch, roll);
  return {yaw, pitch, roll};
}

double wrap_angle(double a) {
  return std::remainder(a, 2.0 * std::numbers::pi);
}

}  // namespace

mrpt::poses::CPose3DPDFGaussian make_pose_pdf(const Eigen::Vector3d& translation,
                                              const Eigen::Matrix3d& translation_covariance,
                                              const Eigen::Quaterniond& orientation,
                                              const Eigen::Matrix3d& tangent_covariance) {
  // Central differences of ypr(q * exp(delta)); the step is small against any covariance we carry
  // and large against rounding. Angle wrap keeps the differences finite across +-pi.
  constexpr double kStep = 1e-6;
  Eigen::Matrix3d jacobian;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d delta = Eigen::Vector3d::Zero();
    delta[i] = kStep;
    const Eigen::Vector3d plus = yaw_pitch_roll(orientation * so3::exp(delta));
    const Eigen::Vector3d minus = yaw_pitch_roll(orientation * so3::exp(-delta));
    for (int r = 0; r < 3; ++r) jacobian(r, i) = wrap_angle(plus[r] - minus[r]) / (2.0 * kStep);
  }
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();
  covariance.topLeftCorner<3, 3>() = translation_covariance;
  covariance.bottomRightCorner<3, 3>() = jacobian * tangent_covariance * jacobian.transpose();
  return mrpt::poses::CPose3DPDFGaussian(make_pose(translation, orientation),
                                         mrpt::math::CMatrixDouble66(covariance));
}

}  // namespace opf
