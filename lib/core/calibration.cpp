#include "opf/core/calibration.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/so3.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <limits>

namespace opf {
namespace {

double normalised_squared(const Eigen::Vector3d& error, const Eigen::Matrix3d& covariance) {
  const Eigen::LLT<Eigen::Matrix3d> factor(covariance);
  if (factor.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
  // A factor with a zero pivot "succeeds" on some inputs; its solve would divide by zero.
  if (!(factor.matrixL().toDenseMatrix().diagonal().minCoeff() > 0.0))
    return std::numeric_limits<double>::infinity();
  return error.dot(factor.solve(error));
}

}  // namespace

double translation_nees(const Estimate& estimate, const mrpt::poses::CPose3D& truth) {
  const Eigen::Vector3d error = translation_of(estimate.pose.mean) - translation_of(truth);
  const Eigen::Matrix3d covariance = estimate.pose.cov.asEigen().topLeftCorner<3, 3>();
  return normalised_squared(error, covariance);
}

double rotation_nees(const Estimate& estimate, const mrpt::poses::CPose3D& truth) {
  const Eigen::Vector3d error =
      so3::difference(orientation_of(estimate.pose.mean), orientation_of(truth));
  const Eigen::Matrix3d jacobian = yaw_pitch_roll_jacobian(estimate.pose.mean);
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(jacobian);
  if (!lu.isInvertible()) return std::numeric_limits<double>::infinity();
  const Eigen::Matrix3d inverse = lu.inverse();
  const Eigen::Matrix3d ypr = estimate.pose.cov.asEigen().bottomRightCorner<3, 3>();
  const Eigen::Matrix3d tangent = inverse * ypr * inverse.transpose();
  return normalised_squared(error, 0.5 * (tangent + tangent.transpose()));
}

}  // namespace opf
