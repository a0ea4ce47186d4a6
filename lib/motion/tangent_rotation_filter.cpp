#include "opf/motion/tangent_rotation_filter.h"

#include "opf/core/so3.h"

#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace opf {

std::string_view rotation_model_name(RotationModel model) {
  switch (model) {
    case RotationModel::kConstantOrientation:
      return "constant_orientation";
    case RotationModel::kConstantAngularVelocity:
      return "constant_angular_velocity";
    case RotationModel::kDampedAngularVelocity:
      return "damped_angular_velocity";
  }
  return "unknown";
}

TangentRotationFilter::TangentRotationFilter(RotationModel model, double intensity,
                                             double time_constant)
    : model_(model), intensity_(intensity), time_constant_(time_constant) {
  if (model == RotationModel::kDampedAngularVelocity &&
      !(time_constant > 0.0 && std::isfinite(time_constant)))
    throw std::invalid_argument(
        "TangentRotationFilter: damped angular velocity needs a positive time constant (s)");
}

void TangentRotationFilter::initialise(const Eigen::Quaterniond& orientation,
                                       double orientation_std, double rate_std,
                                       const Eigen::Vector3d& rate) {
  orientation_ = orientation.normalized();
  angular_velocity_.setZero();
  if (has_rate()) angular_velocity_ = rate;
  covariance_.setZero();
  covariance_.topLeftCorner<3, 3>().diagonal().setConstant(orientation_std * orientation_std);
  if (has_rate()) covariance_.bottomRightCorner<3, 3>().diagonal().setConstant(rate_std * rate_std);
}

AxisMotionModel TangentRotationFilter::axis_model() const {
  switch (model_) {
    case RotationModel::kConstantOrientation:
      return {MotionModel::kConstantPosition, intensity_, 1.0, 0.0};
    case RotationModel::kConstantAngularVelocity:
      return {MotionModel::kConstantVelocity, intensity_, 1.0, 0.0};
    case RotationModel::kDampedAngularVelocity:
      return {MotionModel::kDampedVelocity, intensity_, time_constant_, 0.0};
  }
  return {};
}

AxisMotionStep TangentRotationFilter::step_for(double dt) const {
  return dt == step_dt_ ? step_ : axis_model().step(dt);
}

void TangentRotationFilter::predict(double dt) {
  predict(dt, step_for(dt));
}

void TangentRotationFilter::predict(double dt, const AxisMotionStep& step) {
  // Per tangent axis (value, rate) steps by the axis model's F = [1 turn; 0 decay] and Q; the
  // rate's turn over the step carries the error through the step's own rotation, so over
  // (dtheta, dw) F = [spin  turn I; 0  decay I], spin = exp(-w turn). With P = [A B; B^T C],
  // F P F^T is formed by blocks (a 6 x 6 product costs three times as much).
  step_ = step;
  step_dt_ = dt;
  const AxisMotionStep& axis = step_;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  if (!has_rate()) {  // w pinned at 0: no turn, the value block random-walks
    covariance_.topLeftCorner<3, 3>() += axis.process_noise(0, 0) * identity;
    return;
  }
  const double turn = axis.transition(0, 1), decay = axis.transition(1, 1);
  const Eigen::Quaterniond step_turn = so3::exp(angular_velocity_ * turn);
  const Eigen::Matrix3d spin = step_turn.conjugate().toRotationMatrix();
  orientation_ = (orientation_ * step_turn).normalized();
  angular_velocity_ *= decay;
  const Eigen::Matrix3d a = covariance_.topLeftCorner<3, 3>();
  const Eigen::Matrix3d b = covariance_.topRightCorner<3, 3>();
  const Eigen::Matrix3d c = covariance_.bottomRightCorner<3, 3>();
  const Eigen::Matrix3d spun_rate = spin * b + turn * c;  // top right of F P
  Eigen::Matrix3d value = (spin * a + turn * b.transpose()) * spin.transpose() + turn * spun_rate;
  value = 0.5 * (value + value.transpose()).eval();
  covariance_.topLeftCorner<3, 3>() = value + axis.process_noise(0, 0) * identity;
  covariance_.topRightCorner<3, 3>() = decay * spun_rate + axis.process_noise(0, 1) * identity;
  covariance_.bottomLeftCorner<3, 3>() = covariance_.topRightCorner<3, 3>().transpose();
  covariance_.bottomRightCorner<3, 3>() = decay * decay * c + axis.process_noise(1, 1) * identity;
}

kalman::Correction<6, 3> TangentRotationFilter::update(
    const Eigen::Quaterniond& measured, double variance,
    const std::optional<kalman::StudentTNoise>& heavy_tails) {
  // H = [I 0]: H P H^T is P's value block and P H^T its value columns X, so the update is
  // P <- P - X S^-1 X^T with S = A + R, R = variance I, and the correction X S^-1 r.
  const Eigen::Vector3d residual = so3::difference(orientation_, measured);
  const Eigen::Matrix3d a = covariance_.topLeftCorner<3, 3>();
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  // S is symmetric positive definite and 3 x 3: its closed-form inverse (cofactors over the
  // determinant) is as accurate as a factorisation here and a fraction of its cost.
  const Eigen::Matrix3d s = a + variance * identity;
  const Eigen::Matrix3d s_inverse = s.inverse();
  kalman::Correction<6, 3> out;
  out.innovation = residual;
  out.squared_distance = residual.dot(s_inverse * residual);
  out.determinant = s.determinant();
  Eigen::Matrix3d gain_inverse = s_inverse;  // S^-1 of the noise the update takes
  if (heavy_tails) {
    // Student-t noise (linear_kalman.h, update_covariance_student_t): R scaled by the posterior
    // mean of 1 / w; the density, Student-t's, left to the caller as there.
    out.log_likelihood = std::numeric_limits<double>::quiet_NaN();
    const double scale = kalman::student_t_noise_scale(*heavy_tails, out.squared_distance, 3);
    gain_inverse = (a + variance * scale * identity).inverse();
  } else {
    out.log_likelihood =
        kalman::gaussian_log_density(out.squared_distance, std::log(out.determinant), 3);
  }
  // K = [A; B^T] G, G that S^-1 (symmetric): the correction K r, and P <- P - K [A B] by blocks,
  // the symmetric ones symmetrised (a 6 x 6 product costs twice as much, and without a rate B and
  // C stay 0).
  const Eigen::Vector3d weighed = gain_inverse * residual;
  const Eigen::Matrix3d b = covariance_.topRightCorner<3, 3>();
  out.correction << a * weighed, b.transpose() * weighed;
  const Eigen::Matrix3d value = a - a * (gain_inverse * a);
  covariance_.topLeftCorner<3, 3>() = 0.5 * (value + value.transpose());
  if (has_rate()) {
    const Eigen::Matrix3d weighed_rate = gain_inverse * b;  // G B
    const Eigen::Matrix3d rate =
        covariance_.bottomRightCorner<3, 3>() - b.transpose() * weighed_rate;
    covariance_.topRightCorner<3, 3>() = b - a * weighed_rate;
    covariance_.bottomLeftCorner<3, 3>() = covariance_.topRightCorner<3, 3>().transpose();
    covariance_.bottomRightCorner<3, 3>() = 0.5 * (rate + rate.transpose());
  }
  // The reset Jacobian I - [dtheta/2]x is left out, as in the Kalman baselines: a relative
  // O(|dtheta|) change of P.
  orientation_ = (orientation_ * so3::exp(out.correction.head<3>())).normalized();
  if (has_rate()) angular_velocity_ += out.correction.tail<3>();
  return out;
}

double TangentRotationFilter::orientation_variance_growth(double horizon) const {
  // predict()'s value block is spin A spin^T + turn (B^T spin^T + spin B) + turn^2 C + Q: the
  // turn leaves A's trace as it is.
  const AxisMotionStep axis = step_for(horizon);
  const double turn = axis.transition(0, 1);
  const Eigen::Matrix3d spin = so3::exp(angular_velocity_ * turn).conjugate().toRotationMatrix();
  return 2.0 * turn * (spin * covariance_.topRightCorner<3, 3>()).trace() +
         turn * turn * covariance_.bottomRightCorner<3, 3>().trace() +
         3.0 * axis.process_noise(0, 0);
}

TangentRotationFilter::Prediction TangentRotationFilter::predicted(double horizon) const {
  return predicted(horizon, step_for(horizon));
}

TangentRotationFilter::Prediction TangentRotationFilter::predicted(
    double horizon, const AxisMotionStep& step) const {
  TangentRotationFilter ahead = *this;
  ahead.predict(horizon, step);
  return {ahead.orientation_, ahead.covariance_.topLeftCorner<3, 3>()};
}

}  // namespace opf
