#include "opf/estimators/cv_kalman.h"

#include "opf/core/pose_conversion.h"

#include <cmath>
#include <stdexcept>

namespace opf {
namespace {

// The position is measured directly: H = [I 0].
kalman::Matrix<3, 6> position_observation() {
  kalman::Matrix<3, 6> h = kalman::Matrix<3, 6>::Zero();
  h.leftCols<3>().setIdentity();
  return h;
}

}  // namespace

ConstantVelocityKalman::ConstantVelocityKalman(const CvKalmanOptions& options)
    : options_(options),
      rotation_(RotationModel::kConstantAngularVelocity, options.angular_acceleration_noise) {
  check_options(options_, "cvkf");
}

Estimate ConstantVelocityKalman::initialise(double t,
                                            const mrpt::poses::CPose3D& first_measurement) {
  t_ = t;
  translation_ << translation_of(first_measurement), Eigen::Vector3d::Zero();
  const double sigma_t = options_.observation_noise_translation;
  const double sigma_v = options_.initial_velocity_std;
  translation_covariance_.setZero();
  translation_covariance_.topLeftCorner<3, 3>().diagonal().setConstant(sigma_t * sigma_t);
  translation_covariance_.bottomRightCorner<3, 3>().diagonal().setConstant(sigma_v * sigma_v);
  rotation_.initialise(orientation_of(first_measurement), options_.observation_noise_rotation,
                       options_.initial_angular_velocity_std);
  initialised_ = true;
  return make_estimate(EstimateMode::kMeasured);
}

Estimate ConstantVelocityKalman::step(double t, const mrpt::poses::CPose3D* measurement,
                                      const EnsembleView& ensemble) {
  if (!initialised_) throw std::logic_error("ConstantVelocityKalman: step() before initialise()");
  const double dt = time_step("ConstantVelocityKalman", t_, t);
  t_ = t;
  predict(dt);
  if (measurement == nullptr) return make_estimate(EstimateMode::kPredicted);
  update(*measurement, stated_extra_noise(ensemble, measurement));
  return make_estimate(EstimateMode::kMeasured);
}

void ConstantVelocityKalman::predict(double dt) {
  kalman::predict(translation_, translation_covariance_,
                  kalman::constant_rate_transition(Eigen::Matrix3d::Identity(), dt),
                  kalman::white_noise_acceleration(options_.acceleration_noise, dt));
  rotation_.predict(dt);
}

void ConstantVelocityKalman::update(const mrpt::poses::CPose3D& measurement, double extra_noise) {
  const double sigma_t = observation_sigma(options_.observation_noise_translation, extra_noise);
  kalman::update<6, 3>(translation_, translation_covariance_, position_observation(),
                       sigma_t * sigma_t * Eigen::Matrix3d::Identity(),
                       translation_of(measurement));
  const double sigma_r = options_.observation_noise_rotation;
  rotation_.update(orientation_of(measurement), sigma_r * sigma_r);
}

Estimate ConstantVelocityKalman::make_estimate(EstimateMode mode) const {
  const double sigma_t = options_.observation_noise_translation;
  const double sigma_r = options_.observation_noise_rotation;
  Estimate estimate;
  estimate.t = t_;
  estimate.pose =
      make_pose_pdf(translation_.head<3>(), translation_covariance_.topLeftCorner<3, 3>(),
                    rotation_.orientation(), rotation_.covariance().topLeftCorner<3, 3>());
  estimate.observation_trace = 3.0 * sigma_t * sigma_t + 3.0 * sigma_r * sigma_r;
  estimate.mode = mode;
  return estimate;
}

}  // namespace opf
