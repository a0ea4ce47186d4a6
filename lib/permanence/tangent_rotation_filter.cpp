#include "opf/permanence/tangent_rotation_filter.h"

#include "opf/core/so3.h"

namespace opf {

std::string_view rotation_model_name(RotationModel model) {
  return model == RotationModel::kConstantOrientation ? "constant_orientation"
                                                      : "constant_angular_velocity";
}

void TangentRotationFilter::initialise(const Eigen::Quaterniond& orientation,
                                       double orientation_std, double rate_std,
                                       const Eigen::Vector3d& rate) {
  orientation_ = orientation.normalized();
  angular_velocity_.setZero();
  if (model_ == RotationModel::kConstantAngularVelocity) angular_velocity_ = rate;
  covariance_.setZero();
  covariance_.topLeftCorner<3, 3>().diagonal().setConstant(orientation_std * orientation_std);
  if (model_ == RotationModel::kConstantAngularVelocity)
    covariance_.bottomRightCorner<3, 3>().diagonal().setConstant(rate_std * rate_std);
}

kalman::LinearModel<6> TangentRotationFilter::step(double dt) const {
  const double q2 = intensity_ * intensity_;
  if (model_ == RotationModel::kConstantOrientation) {
    kalman::LinearModel<6> m{kalman::Matrix<6>::Zero(), kalman::Matrix<6>::Zero()};
    m.transition.topLeftCorner<3, 3>().setIdentity();
    m.process_noise.topLeftCorner<3, 3>().diagonal().setConstant(q2 * dt);
    return m;
  }
  return {
      kalman::constant_rate_transition(so3::exp(-angular_velocity_ * dt).toRotationMatrix(), dt),
      kalman::white_noise_acceleration(intensity_, dt)};
}

void TangentRotationFilter::predict(double dt) {
  const kalman::LinearModel<6> m = step(dt);
  orientation_ = (orientation_ * so3::exp(angular_velocity_ * dt)).normalized();
  kalman::predict_covariance(covariance_, m.transition, m.process_noise);
}

kalman::Correction<6, 3> TangentRotationFilter::update(
    const Eigen::Quaterniond& measured, double variance,
    const std::optional<kalman::StudentTNoise>& heavy_tails) {
  kalman::Matrix<3, 6> h = kalman::Matrix<3, 6>::Zero();
  h.leftCols<3>().setIdentity();
  const Eigen::Matrix3d noise = variance * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d residual = so3::difference(orientation_, measured);
  const auto correction =
      heavy_tails
          ? kalman::update_covariance_student_t<6, 3>(covariance_, h, noise, residual, *heavy_tails)
          : kalman::update_covariance<6, 3>(covariance_, h, noise, residual);
  // The reset Jacobian I - [dtheta/2]x is left out, as in the Kalman baselines: a relative
  // O(|dtheta|) change of P.
  orientation_ = (orientation_ * so3::exp(correction.correction.head<3>())).normalized();
  if (model_ == RotationModel::kConstantAngularVelocity)
    angular_velocity_ += correction.correction.tail<3>();
  return correction;
}

TangentRotationFilter::Prediction TangentRotationFilter::predicted(double horizon) const {
  TangentRotationFilter ahead = *this;
  ahead.predict(horizon);
  return {ahead.orientation_, ahead.covariance_.topLeftCorner<3, 3>()};
}

}  // namespace opf
