#include "opf/estimators/orientation_kalman.h"

#include "opf/core/so3.h"

namespace opf {

void OrientationKalman::initialise(const Eigen::Quaterniond& orientation, double orientation_std,
                                   double rate_std) {
  orientation_ = orientation;
  angular_velocity_.setZero();
  covariance_.setZero();
  covariance_.topLeftCorner<3, 3>().diagonal().setConstant(orientation_std * orientation_std);
  covariance_.bottomRightCorner<3, 3>().diagonal().setConstant(rate_std * rate_std);
}

void OrientationKalman::predict(double dt, double angular_acceleration_noise) {
  // The error dtheta lives at the end of the step in the body frame, so an error at its start is
  // carried through the step's own rotation: Exp(-w dt). The dw -> dtheta block is the first-order
  // dt I rather than J_r(w dt) dt (J_r the right Jacobian); they differ by a relative O(|w dt|).
  const kalman::Matrix<6> f =
      kalman::constant_rate_transition(so3::exp(-angular_velocity_ * dt).toRotationMatrix(), dt);
  orientation_ = (orientation_ * so3::exp(angular_velocity_ * dt)).normalized();
  kalman::predict_covariance(covariance_, f,
                             kalman::white_noise_acceleration(angular_acceleration_noise, dt));
}

void OrientationKalman::update(const Eigen::Quaterniond& measured, double variance) {
  // The orientation is measured directly: H = [I 0]. so3::difference takes the shorter way round.
  kalman::Matrix<3, 6> h = kalman::Matrix<3, 6>::Zero();
  h.leftCols<3>().setIdentity();
  const auto update =
      kalman::update_covariance<6, 3>(covariance_, h, variance * Eigen::Matrix3d::Identity(),
                                      so3::difference(orientation_, measured));
  // Injecting dtheta and resetting it to zero should also map the covariance through the reset
  // Jacobian I - [dtheta/2]x. It is left out, as is usual: it changes P by a relative O(|dtheta|),
  // and dtheta is a fraction of the residual, O(sigma_r) once converged (larger only on the first
  // update after a long gap, when P is large anyway).
  orientation_ = (orientation_ * so3::exp(update.correction.head<3>())).normalized();
  angular_velocity_ += update.correction.tail<3>();
}

}  // namespace opf
