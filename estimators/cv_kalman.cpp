#include "opf/estimators/cv_kalman.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/so3.h"

#include <Eigen/Cholesky>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace opf {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

// Exact discretisation of continuous white-noise acceleration of density q^2 per axis over dt:
// the covariance the (value, rate) pair accumulates when the rate random-walks in between.
Matrix6 white_noise_acceleration(double q, double dt) {
  const double q2 = q * q;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  Matrix6 noise;
  noise.topLeftCorner<3, 3>() = q2 * dt * dt * dt / 3.0 * identity;
  noise.topRightCorner<3, 3>() = q2 * dt * dt / 2.0 * identity;
  noise.bottomLeftCorner<3, 3>() = q2 * dt * dt / 2.0 * identity;
  noise.bottomRightCorner<3, 3>() = q2 * dt * identity;
  return noise;
}

Matrix6 transition(const Eigen::Matrix3d& value_block, double dt) {
  Matrix6 f = Matrix6::Identity();
  f.topLeftCorner<3, 3>() = value_block;
  f.topRightCorner<3, 3>() = dt * Eigen::Matrix3d::Identity();
  return f;
}

// Update of a (value, rate) state whose value is measured directly (H = [I 0]) with isotropic
// noise `variance`; returns the state correction. The Joseph form keeps the covariance symmetric
// positive definite under rounding, which the short form does not once the gain is large.
Vector6 update_value(Matrix6& covariance, const Eigen::Vector3d& residual, double variance) {
  const Eigen::Matrix3d innovation =
      covariance.topLeftCorner<3, 3>() + variance * Eigen::Matrix3d::Identity();
  // K = P H^T S^-1, solved as S K^T = H P since both P and S are symmetric.
  const Eigen::Matrix<double, 6, 3> gain =
      innovation.ldlt().solve(covariance.topRows<3>()).transpose();
  Matrix6 a = Matrix6::Identity();
  a.leftCols<3>() -= gain;
  covariance = a * covariance * a.transpose() + variance * gain * gain.transpose();
  covariance = 0.5 * (covariance + covariance.transpose()).eval();
  return gain * residual;
}

Matrix6 initial_covariance(double value_std, double rate_std) {
  Matrix6 covariance = Matrix6::Zero();
  covariance.topLeftCorner<3, 3>().diagonal().setConstant(value_std * value_std);
  covariance.bottomRightCorner<3, 3>().diagonal().setConstant(rate_std * rate_std);
  return covariance;
}

}  // namespace

ConstantVelocityKalman::ConstantVelocityKalman(const CvKalmanOptions& options) : options_(options) {
  check_options(options_, "cvkf");
}

Estimate ConstantVelocityKalman::initialise(double t,
                                            const mrpt::poses::CPose3D& first_measurement) {
  t_ = t;
  position_ = translation_of(first_measurement);
  velocity_.setZero();
  translation_covariance_ =
      initial_covariance(options_.observation_noise_translation, options_.initial_velocity_std);
  orientation_ = orientation_of(first_measurement);
  angular_velocity_.setZero();
  rotation_covariance_ = initial_covariance(options_.observation_noise_rotation,
                                            options_.initial_angular_velocity_std);
  initialised_ = true;
  return make_estimate(EstimateMode::kMeasured);
}

Estimate ConstantVelocityKalman::step(double t, const mrpt::poses::CPose3D* measurement,
                                      const EnsembleView& /*ensemble*/) {
  if (!initialised_) throw std::logic_error("ConstantVelocityKalman: step() before initialise()");
  const double dt = t - t_;
  if (!(dt > 0.0)) {
    std::ostringstream msg;
    msg << "ConstantVelocityKalman: time " << t << " s does not follow the previous time " << t_
        << " s";
    throw std::invalid_argument(msg.str());
  }
  t_ = t;
  predict(dt);
  if (measurement == nullptr) return make_estimate(EstimateMode::kPredicted);
  update(*measurement);
  return make_estimate(EstimateMode::kMeasured);
}

void ConstantVelocityKalman::predict(double dt) {
  const Matrix6 f_translation = transition(Eigen::Matrix3d::Identity(), dt);
  position_ += dt * velocity_;
  translation_covariance_ = f_translation * translation_covariance_ * f_translation.transpose() +
                            white_noise_acceleration(options_.acceleration_noise, dt);

  // The error dtheta lives at the end of the step in the body frame, so an error at its start is
  // carried through the step's own rotation: Exp(-w dt). The dw -> dtheta block is the first-order
  // dt I rather than J_r(w dt) dt (J_r the right Jacobian); they differ by a relative O(|w dt|).
  const Matrix6 f_rotation = transition(so3::exp(-angular_velocity_ * dt).toRotationMatrix(), dt);
  orientation_ = (orientation_ * so3::exp(angular_velocity_ * dt)).normalized();
  rotation_covariance_ = f_rotation * rotation_covariance_ * f_rotation.transpose() +
                         white_noise_acceleration(options_.angular_acceleration_noise, dt);
}

void ConstantVelocityKalman::update(const mrpt::poses::CPose3D& measurement) {
  const double sigma_t = options_.observation_noise_translation;
  const Vector6 translation_correction = update_value(
      translation_covariance_, translation_of(measurement) - position_, sigma_t * sigma_t);
  position_ += translation_correction.head<3>();
  velocity_ += translation_correction.tail<3>();

  // so3::difference takes the shorter way round, so the sign of either quaternion is irrelevant.
  const double sigma_r = options_.observation_noise_rotation;
  const Vector6 rotation_correction =
      update_value(rotation_covariance_, so3::difference(orientation_, orientation_of(measurement)),
                   sigma_r * sigma_r);
  // Injecting dtheta and resetting it to zero should also map the covariance through the reset
  // Jacobian I - [dtheta/2]x. It is left out, as is usual: it changes P by a relative O(|dtheta|),
  // and dtheta is a fraction of the residual, O(sigma_r) once converged (larger only on the first
  // update after a long gap, when P is large anyway).
  orientation_ = (orientation_ * so3::exp(rotation_correction.head<3>())).normalized();
  angular_velocity_ += rotation_correction.tail<3>();
}

Estimate ConstantVelocityKalman::make_estimate(EstimateMode mode) const {
  const double sigma_t = options_.observation_noise_translation;
  const double sigma_r = options_.observation_noise_rotation;
  Estimate estimate;
  estimate.t = t_;
  estimate.pose = make_pose_pdf(position_, translation_covariance_.topLeftCorner<3, 3>(),
                                orientation_, rotation_covariance_.topLeftCorner<3, 3>());
  estimate.observation_trace = 3.0 * sigma_t * sigma_t + 3.0 * sigma_r * sigma_r;
  estimate.mode = mode;
  return estimate;
}

}  // namespace opf
