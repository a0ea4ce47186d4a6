#pragma once
// The orientation half of the Kalman baselines (cvkf, imm): an error-state Kalman filter on the
// orientation and its body-frame angular velocity, the error dtheta in the tangent space at the
// current estimate, the rate under white-noise angular acceleration (core/linear_kalman.h).

#include "opf/core/linear_kalman.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace opf {

class OrientationKalman {
 public:
  /// At `orientation` with std `orientation_std` (rad, per tangent axis), the rate zero with std
  /// `rate_std` (rad/s).
  void initialise(const Eigen::Quaterniond& orientation, double orientation_std, double rate_std);

  /// Rotates by the rate over dt; `angular_acceleration_noise` in rad/s^2/sqrt(Hz).
  void predict(double dt, double angular_acceleration_noise);

  /// Updates with a measured orientation of isotropic tangent-space variance `variance` (rad^2);
  /// the sign of either quaternion is irrelevant.
  void update(const Eigen::Quaterniond& measured, double variance);

  const Eigen::Quaterniond& orientation() const { return orientation_; }
  const Eigen::Vector3d& angular_velocity() const { return angular_velocity_; }
  /// Over the error state (dtheta, dw).
  const kalman::Matrix<6>& covariance() const { return covariance_; }

 private:
  Eigen::Quaterniond orientation_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d angular_velocity_ = Eigen::Vector3d::Zero();  ///< body frame
  kalman::Matrix<6> covariance_ = kalman::Matrix<6>::Identity();
};

}  // namespace opf
