#include "opf/permanence/rotation_model_bank.h"

#include "opf/core/so3.h"
#include "opf/particles/student_t_densities.h"
#include "opf/permanence/weighted_choice.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace opf {
namespace {

std::vector<TangentRotationFilter> members_of(const RotationModelBankOptions& options) {
  validate(options);
  std::vector<TangentRotationFilter> members;
  if (options.constant_orientation)
    for (const double factor : kBankIntensityFactors)
      members.emplace_back(RotationModel::kConstantOrientation,
                           factor * kRotationBankOrientationNoiseBase * options.intensity_scale);
  if (options.constant_angular_velocity)
    for (const double factor : kBankIntensityFactors)
      members.emplace_back(
          RotationModel::kConstantAngularVelocity,
          factor * kRotationBankAngularAccelerationNoiseBase * options.intensity_scale);
  if (options.damped_angular_velocity)
    for (const double factor : kBankIntensityFactors)
      for (const double time_constant : kBankDampingTimeConstants)
        members.emplace_back(
            RotationModel::kDampedAngularVelocity,
            factor * kRotationBankAngularAccelerationNoiseBase * options.intensity_scale,
            time_constant);
  return members;
}

std::vector<double> priors_of(const std::vector<TangentRotationFilter>& members) {
  std::vector<int> model_of_member;
  for (const TangentRotationFilter& f : members)
    model_of_member.push_back(static_cast<int>(f.model()));
  return equal_model_priors(model_of_member);
}

std::vector<AxisMotionModel> axis_models_of(const std::vector<TangentRotationFilter>& members) {
  std::vector<AxisMotionModel> out;
  for (const TangentRotationFilter& f : members) out.push_back(f.axis_model());
  return out;
}

}  // namespace

RotationModelBank::RotationModelBank(const RotationModelBankOptions& options)
    : options_(options),
      filters_(members_of(options)),
      axis_models_(axis_models_of(filters_)),
      surprises_(filters_.size(), 0),
      weights_(priors_of(filters_)),
      determinants_(filters_.size(), 0.0),
      squared_distances_(filters_.size(), 0.0),
      log_likelihoods_(filters_.size(), 0.0) {}

void RotationModelBank::update(double t, const Eigen::Quaterniond& orientation) {
  if (!std::isfinite(t) || !orientation.coeffs().allFinite() || orientation.norm() == 0.0)
    throw std::invalid_argument(
        "RotationModelBank: update() with a non-finite time or orientation");
  const double sigma = options_.observation_noise;
  if (!initialised_) {
    for (TangentRotationFilter& f : filters_)
      f.initialise(orientation, sigma, options_.initial_angular_velocity_std);
    weights_.reset();
    t_ = t;
    last_orientation_ = orientation;
    initialised_ = true;
    return;
  }
  const double dt = t - t_;
  if (dt < 0.0)
    throw std::invalid_argument("RotationModelBank: update() at t = " + std::to_string(t) +
                                " s, before the last one at " + std::to_string(t_) + " s");
  t_ = t;
  if (dt != steps_dt_) {
    steps_over(axis_models_, dt, steps_);
    steps_dt_ = dt;
  }
  for (std::size_t j = 0; j < filters_.size(); ++j) {
    TangentRotationFilter& f = filters_[j];
    f.predict(dt, steps_[j]);
    const auto correction = f.update(orientation, sigma * sigma, noise_model_);
    determinants_[j] = correction.determinant;
    squared_distances_[j] = correction.squared_distance;
    surprises_[j] = correction.squared_distance > kRotationGateChiSquare ? surprises_[j] + 1 : 0;
    if (surprises_[j] >= kSurprisesToRestart) {
      // Restarted from the last two orientations: the body rate is their difference's slope.
      const Eigen::Vector3d rate =
          dt > 0.0 ? Eigen::Vector3d(so3::difference(last_orientation_, orientation) / dt)
                   : Eigen::Vector3d::Zero();
      f.initialise(orientation, sigma,
                   dt > 0.0 ? std::sqrt(2.0) * sigma / dt : options_.initial_angular_velocity_std,
                   rate);
      surprises_[j] = 0;
    }
  }
  last_orientation_ = orientation;
  student_t_log_densities(noise_model_, 3, determinants_, squared_distances_, log_likelihoods_);
  weights_.update(dt, options_.memory, log_likelihoods_);
}

RotationMemberPrediction RotationModelBank::member_prediction(std::size_t index,
                                                              double horizon) const {
  if (index >= filters_.size())
    throw std::out_of_range("RotationModelBank: no member " + std::to_string(index));
  if (!initialised_) throw std::logic_error("RotationModelBank: predict() before any update()");
  if (!(horizon >= 0.0) || !std::isfinite(horizon))
    throw std::invalid_argument("RotationModelBank: the horizon must be a finite number >= 0 (s)");
  const TangentRotationFilter::Prediction p = filters_[index].predicted(horizon);
  return {rotation_model_name(filters_[index].model()), weights_.weights()[index], p.orientation,
          p.covariance};
}

std::vector<RotationMemberPrediction> RotationModelBank::predict(double horizon) const {
  std::vector<RotationMemberPrediction> out;
  predict(horizon, out);
  return out;
}

void RotationModelBank::predict(double horizon, std::vector<RotationMemberPrediction>& out) const {
  if (!initialised_) throw std::logic_error("RotationModelBank: predict() before any update()");
  if (!(horizon >= 0.0) || !std::isfinite(horizon))
    throw std::invalid_argument("RotationModelBank: the horizon must be a finite number >= 0 (s)");
  std::vector<AxisMotionStep> scratch;
  const std::vector<AxisMotionStep>& steps = steps_at(horizon, scratch);
  out.resize(filters_.size());
  for (std::size_t j = 0; j < filters_.size(); ++j) {
    const TangentRotationFilter::Prediction p = filters_[j].predicted(horizon, steps[j]);
    out[j] = {rotation_model_name(filters_[j].model()), weights_.weights()[j], p.orientation,
              p.covariance};
  }
}

double RotationModelBank::variance_growth(double horizon) const {
  if (!initialised_) throw std::logic_error("RotationModelBank: predict() before any update()");
  double growth = 0.0;
  for (std::size_t j = 0; j < filters_.size(); ++j)
    growth += weights_.weights()[j] * filters_[j].orientation_variance_growth(horizon);
  return growth / 3.0;
}

Eigen::Vector3d RotationModelBank::angular_velocity() const {
  Eigen::Vector3d rate = Eigen::Vector3d::Zero();
  for (std::size_t j = 0; j < filters_.size(); ++j)
    rate += weights_.weights()[j] * filters_[j].angular_velocity();
  return rate;
}

double RotationModelBank::model_weight(RotationModel model) const {
  double sum = 0.0;
  for (std::size_t j = 0; j < filters_.size(); ++j)
    if (filters_[j].model() == model) sum += weights_.weights()[j];
  return sum;
}

std::size_t RotationModelBank::sample_member(double uniform01) const {
  return weighted_choice(weights_.weights(), uniform01);
}

const std::vector<AxisMotionStep>& RotationModelBank::steps_at(
    double dt, std::vector<AxisMotionStep>& scratch) const {
  if (dt == steps_dt_) return steps_;  // exactly: as each member's own filter compares
  steps_over(axis_models_, dt, scratch);
  return scratch;
}

}  // namespace opf
