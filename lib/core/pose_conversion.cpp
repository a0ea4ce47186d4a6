#include "opf/core/pose_conversion.h"

#include "opf/core/so3.h"

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/CQuaternion.h>

#include <cmath>

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

Eigen::Matrix3d yaw_pitch_roll_jacobian(const mrpt::poses::CPose3D& pose) {
  // MRPT's R = Rz(yaw) Ry(pitch) Rx(roll); a body-frame step delta is a body angular velocity,
  // and the Euler rates of a body angular velocity w are (Euler-angle kinematics, ZYX):
  //   yaw'   = (sin(roll) w_y + cos(roll) w_z) / cos(pitch)
  //   pitch' =  cos(roll) w_y - sin(roll) w_z
  //   roll'  =  w_x + tan(pitch) (sin(roll) w_y + cos(roll) w_z)
  // singular at pitch = +-pi/2 (gimbal lock), as any Euler-angle covariance is.
  const double pitch = pose.pitch(), roll = pose.roll();
  const double sr = std::sin(roll), cr = std::cos(roll);
  const double cp = std::cos(pitch), tp = std::tan(pitch);
  Eigen::Matrix3d jacobian;
  jacobian << 0.0, sr / cp, cr / cp,  //
      0.0, cr, -sr,                   //
      1.0, sr * tp, cr * tp;
  return jacobian;
}

mrpt::poses::CPose3DPDFGaussian make_pose_pdf(const Eigen::Vector3d& translation,
                                              const Eigen::Matrix3d& translation_covariance,
                                              const Eigen::Quaterniond& orientation,
                                              const Eigen::Matrix3d& tangent_covariance) {
  mrpt::poses::CPose3D pose = make_pose(translation, orientation);
  const Eigen::Matrix3d jacobian = yaw_pitch_roll_jacobian(pose);
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();
  covariance.topLeftCorner<3, 3>() = translation_covariance;
  covariance.bottomRightCorner<3, 3>() = jacobian * tangent_covariance * jacobian.transpose();
  return mrpt::poses::CPose3DPDFGaussian(pose, mrpt::math::CMatrixDouble66(covariance));
}

}  // namespace opf
