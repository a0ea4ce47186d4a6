#include "opf/estimators/imm_kalman.h"

#include "opf/core/pose_conversion.h"

#include <cmath>
#include <stdexcept>

namespace opf {
namespace {

// The position is measured directly: H = [1 0 0] on each axis.
const kalman::Matrix<1, 3> kPositionObservation(1.0, 0.0, 0.0);

}  // namespace

ImmKalman::ImmKalman(const ImmOptions& options)
    : options_(options),
      rotation_(RotationModel::kConstantAngularVelocity, options.angular_acceleration_noise) {
  check_options(options_, "imm");
}

Estimate ImmKalman::initialise(double t, const mrpt::poses::CPose3D& first_measurement) {
  t_ = t;
  const Eigen::Vector3d position = translation_of(first_measurement);
  const double sigma_t = options_.observation_noise_translation;
  const double sigma_v = options_.initial_velocity_std;
  const double sigma_a = options_.initial_acceleration_std;
  Gaussian prior;
  prior.covariance =
      kalman::Vector<3>(sigma_t * sigma_t, sigma_v * sigma_v, sigma_a * sigma_a).asDiagonal();
  for (int axis = 0; axis < 3; ++axis) {
    prior.mean << position[axis], 0.0, 0.0;
    banks_[axis].fill(prior);
  }
  probabilities_.setConstant(1.0 / kModels);
  combine();
  rotation_.initialise(orientation_of(first_measurement), options_.observation_noise_rotation,
                       options_.initial_angular_velocity_std);
  initialised_ = true;
  return make_estimate(EstimateMode::kMeasured);
}

Estimate ImmKalman::step(double t, const mrpt::poses::CPose3D* measurement,
                         const EnsembleView& ensemble) {
  if (!initialised_) throw std::logic_error("ImmKalman: step() before initialise()");
  const double dt = time_step("ImmKalman", t_, t);
  t_ = t;
  const double sigma_r = options_.observation_noise_rotation;
  rotation_.predict(dt);
  if (measurement == nullptr) {
    predict_and_update(dt, nullptr, 0.0);
    return make_estimate(EstimateMode::kPredicted);
  }
  const Eigen::Vector3d position = translation_of(*measurement);
  predict_and_update(dt, &position, stated_extra_noise(ensemble, measurement));
  rotation_.update(orientation_of(*measurement), sigma_r * sigma_r);
  return make_estimate(EstimateMode::kMeasured);
}

void ImmKalman::predict_and_update(double dt, const Eigen::Vector3d* position, double extra_noise) {
  // Markov switching in continuous time: a model is left at the rate 1/tau, to each other one
  // equally (generator G = (J - M I) / ((M - 1) tau), M models, J all ones). Over dt the chain
  // moves by exp(G dt): P(i -> j) = (1 - exp(-M dt / ((M - 1) tau))) / M for j != i, the rest
  // stays. exp(-dt / tau) is the probability of no switch at all; the transition also counts
  // leaving and coming back, so that n steps of dt are exactly one step of n dt whatever the
  // frame rate (exp(-dt / tau) as P(stay) would be so only to first order in dt).
  const double to_other =
      -std::expm1(-kModels * dt / ((kModels - 1) * options_.mean_sojourn)) / kModels;
  const double stay = 1.0 - (kModels - 1) * to_other;
  const std::array<kalman::LinearModel<3>, kModels> models = {
      kalman::constant_position_model(options_.position_noise, dt),
      kalman::constant_velocity_model(options_.acceleration_noise, dt),
      kalman::constant_acceleration_model(options_.jerk_noise, dt)};
  const double sigma_t = observation_sigma(options_.observation_noise_translation, extra_noise);
  const kalman::Matrix<1> noise = kalman::Matrix<1>::Constant(sigma_t * sigma_t);

  for (int axis = 0; axis < 3; ++axis) {
    Bank& bank = banks_[axis];
    const Eigen::RowVector3d mu = probabilities_.row(axis);

    // Mixing: c_j = sum_i pi_ij mu_i, mu_i|j = pi_ij mu_i / c_j, and each model-matched filter
    // starts from the moment-matched mixture of all of them under mu_.|j.
    Bank mixed;
    Eigen::RowVector3d predicted;
    for (int j = 0; j < kModels; ++j) {
      Eigen::Vector3d weights;
      for (int i = 0; i < kModels; ++i) weights[i] = (i == j ? stay : to_other) * mu[i];
      predicted[j] = weights.sum();
      weights /= predicted[j];
      Gaussian& m = mixed[j];
      m.mean.setZero();
      for (int i = 0; i < kModels; ++i) m.mean += weights[i] * bank[i].mean;
      m.covariance.setZero();
      for (int i = 0; i < kModels; ++i) {
        const kalman::Vector<3> d = bank[i].mean - m.mean;
        m.covariance += weights[i] * (bank[i].covariance + d * d.transpose());
      }
    }

    // The model-matched filters, and the model probabilities by their innovations' likelihoods:
    // mu_j ∝ c_j N(r_j; 0, S_j), in logs so that a far measurement cannot underflow them all.
    Eigen::RowVector3d log_posterior = predicted.array().log();
    for (int j = 0; j < kModels; ++j) {
      kalman::predict(mixed[j].mean, mixed[j].covariance, models[j].transition,
                      models[j].process_noise);
      if (position != nullptr)
        log_posterior[j] +=
            kalman::update<3, 1>(mixed[j].mean, mixed[j].covariance, kPositionObservation, noise,
                                 kalman::Vector<1>((*position)[axis]))
                .log_likelihood;
    }
    Eigen::RowVector3d posterior = (log_posterior.array() - log_posterior.maxCoeff()).exp();
    posterior /= posterior.sum();
    posterior = posterior.cwiseMax(kProbabilityFloor);
    posterior /= posterior.sum();

    bank = mixed;
    probabilities_.row(axis) = posterior;
  }
  combine();
}

void ImmKalman::combine() {
  for (int axis = 0; axis < 3; ++axis) {
    const Bank& bank = banks_[axis];
    Gaussian& c = combined_[axis];
    c.mean.setZero();
    for (int j = 0; j < kModels; ++j) c.mean += probabilities_(axis, j) * bank[j].mean;
    c.covariance.setZero();
    for (int j = 0; j < kModels; ++j) {
      const kalman::Vector<3> d = bank[j].mean - c.mean;
      c.covariance += probabilities_(axis, j) * (bank[j].covariance + d * d.transpose());
    }
  }
}

Estimate ImmKalman::make_estimate(EstimateMode mode) const {
  const double sigma_t = options_.observation_noise_translation;
  const double sigma_r = options_.observation_noise_rotation;
  Eigen::Vector3d position;
  Eigen::Matrix3d position_covariance = Eigen::Matrix3d::Zero();  // the axes are independent
  for (int axis = 0; axis < 3; ++axis) {
    position[axis] = combined_[axis].mean[0];
    position_covariance(axis, axis) = combined_[axis].covariance(0, 0);
  }
  Estimate estimate;
  estimate.t = t_;
  estimate.pose = make_pose_pdf(position, position_covariance, rotation_.orientation(),
                                rotation_.covariance().topLeftCorner<3, 3>());
  estimate.observation_trace = 3.0 * sigma_t * sigma_t + 3.0 * sigma_r * sigma_r;
  estimate.mode = mode;
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Index best = 0;
    probabilities_.row(axis).maxCoeff(&best);
    if (axis > 0) estimate.motion_model += ',';
    estimate.motion_model += kModelNames[static_cast<std::size_t>(best)];
  }
  return estimate;
}

}  // namespace opf
