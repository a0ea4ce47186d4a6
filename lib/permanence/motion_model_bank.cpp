#include "opf/permanence/motion_model_bank.h"

#include "opf/core/estimator.h"
#include "opf/motion/ballistic_motion.h"
#include "opf/particles/student_t_densities.h"
#include "opf/permanence/weighted_choice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace opf {
namespace {

// Intervals closer than a nanosecond are one frame rate: a member's step is reused across them.
constexpr double kSameInterval = 1e-9;  // s

// A translation member's gate: the chi-square 99.9% quantile with 1 degree of freedom.
constexpr double kAxisGateChiSquare = 10.828;

void check_axis(int axis) {
  if (axis < 0 || axis > 2)
    throw std::out_of_range("MotionModelBank: axis " + std::to_string(axis) + " is not 0, 1 or 2");
}

}  // namespace

Eigen::Vector3d BankPrediction::mean() const {
  return {axes[0].mean(), axes[1].mean(), axes[2].mean()};
}

Eigen::Vector3d BankPrediction::variance() const {
  return {axes[0].variance(), axes[1].variance(), axes[2].variance()};
}

MotionModelBank::MotionModelBank(const MotionModelBankOptions& options) : options_(options) {
  validate(options_);
  const Eigen::Vector3d up = options_.up.normalized();
  const double scale = options_.intensity_scale;
  for (int axis = 0; axis < 3; ++axis) {
    const double g = -kStandardGravity * up[axis];
    std::vector<AxisMotionModel>& models = models_[axis];
    std::vector<int> model_of_member;
    int model_count = 0;
    const auto add = [&](AxisMotionModel m, double base, bool damped) {
      for (const double factor : kBankIntensityFactors) {
        m.intensity = factor * base * scale;
        if (damped) {
          for (const double time_constant : kBankDampingTimeConstants) {
            m.time_constant = time_constant;
            models.push_back(m);
            model_of_member.push_back(model_count);
          }
        } else {
          models.push_back(m);
          model_of_member.push_back(model_count);
        }
      }
      ++model_count;
    };
    if (options_.constant_position)
      add({MotionModel::kConstantPosition, 0.0, 1.0, 0.0}, kBankPositionNoiseBase, false);
    if (options_.constant_velocity)
      add({MotionModel::kConstantVelocity, 0.0, 1.0, 0.0}, kBankAccelerationNoiseBase, false);
    if (options_.damped_velocity)
      add({MotionModel::kDampedVelocity, 0.0, 1.0, 0.0}, kBankAccelerationNoiseBase, true);
    if (options_.ballistic && !(g == 0.0 && options_.constant_velocity))
      add({MotionModel::kBallistic, 0.0, 1.0, g}, kBankAccelerationNoiseBase, false);

    weights_.emplace_back(equal_model_priors(model_of_member));
    filters_[axis].resize(models.size());
    for (const AxisMotionModel& m : models) {
      const auto same = [&m](const AxisMotionModel& o) {
        return o.model == m.model && o.intensity == m.intensity &&
               o.time_constant == m.time_constant && o.acceleration == m.acceleration;
      };
      const auto found = std::find_if(shapes_.begin(), shapes_.end(), same);
      shape_of_[axis].push_back(static_cast<std::size_t>(found - shapes_.begin()));
      if (found == shapes_.end()) shapes_.push_back(m);
    }
  }
}

void MotionModelBank::update(double t, const Eigen::Vector3d& position, double extra_noise,
                             const PartialViewBias& stretch_prior) {
  if (!std::isfinite(t) || !position.allFinite() || !(extra_noise >= 0.0) ||
      !std::isfinite(extra_noise))
    throw std::invalid_argument(
        "MotionModelBank: update() with a non-finite time, position or noise");
  const double r = options_.observation_noise * options_.observation_noise;
  // A (re)start reads one detection alone: its bias, unknown, counts as noise.
  const double detection_r = r + extra_noise * extra_noise;
  if (!initialised_) {
    for (int axis = 0; axis < 3; ++axis) {
      for (std::size_t j = 0; j < filters_[axis].size(); ++j)
        start(filters_[axis][j], models_[axis][j].model, position[axis], position[axis], 0.0,
              detection_r);
      weights_[axis].reset();
    }
    t_ = t;
    last_position_ = position;
    initialised_ = true;
    return;
  }
  const double dt = t - t_;
  if (dt < 0.0)
    throw std::invalid_argument("MotionModelBank: update() at t = " + std::to_string(t) +
                                " s, before the last one at " + std::to_string(t_) + " s");
  t_ = t;
  // A clean view ends a stretch of partial views; within one, s's covariance with (p, v) moves.
  const bool continues_stretch = in_partial_views_ && extra_noise > 0.0;
  if (in_partial_views_ && extra_noise == 0.0) end_partial_views();
  if (extra_noise > 0.0 && !continues_stretch)
    for (int axis = 0; axis < 3; ++axis)
      for (Filter& f : filters_[axis]) {
        f.bias = stretch_prior.mean[axis];
        f.bias_variance = stretch_prior.variance;
        f.bias_covariance.setZero();
      }
  if (std::abs(dt - steps_dt_) > kSameInterval) {
    steps_over(shapes_, dt, steps_);
    steps_dt_ = dt;
    for (int axis = 0; axis < 3; ++axis)
      for (std::size_t j = 0; j < filters_[axis].size(); ++j)
        filters_[axis][j].step = steps_[shape_of_[axis][j]];
  }
  for (int axis = 0; axis < 3; ++axis) {
    const std::size_t members = filters_[axis].size();
    log_likelihoods_.resize(members);
    determinants_.resize(members);
    squared_distances_.resize(members);
    for (std::size_t j = 0; j < members; ++j) {
      Filter& f = filters_[axis][j];
      kalman::predict(f.mean, f.covariance, f.step.transition, f.step.process_noise);
      f.mean += f.step.offset;
      if (continues_stretch) f.bias_covariance = f.step.transition * f.bias_covariance;
      const auto correction = update_member(f, position[axis], extra_noise, r);
      determinants_[j] = correction.determinant;
      squared_distances_[j] = correction.squared_distance;
      f.surprises = correction.squared_distance > kAxisGateChiSquare ? f.surprises + 1 : 0;
      if (f.surprises >= kSurprisesToRestart)
        start(f, models_[axis][j].model, position[axis], last_position_[axis], dt, detection_r);
    }
    student_t_log_densities(noise_model_, 1, determinants_, squared_distances_, log_likelihoods_);
    weights_[axis].update(dt, options_.memory, log_likelihoods_);
  }
  in_partial_views_ = extra_noise > 0.0;
  last_position_ = position;
}

kalman::Correction<3, 1> MotionModelBank::update_member(Filter& f, double z, double extra_noise,
                                                        double r) const {
  if (extra_noise == 0.0) return update_position(f, z, r);  // s forgotten: (p, v) alone
  const kalman::Matrix<1> noise = kalman::Matrix<1>::Constant(r);
  // The state (p, v, s) measured through H = [1 0 extra_noise], with the usual noise alone white.
  kalman::Vector<3> x;
  x << f.mean, f.bias;
  kalman::Matrix<3> p;
  p << f.covariance, f.bias_covariance, f.bias_covariance.transpose(), f.bias_variance;
  const kalman::Matrix<1, 3> h(1.0, 0.0, extra_noise);
  const auto correction =
      kalman::update_covariance_student_t(p, h, noise, kalman::Vector<1>(z - h * x), noise_model_);
  x += correction.correction;
  f.mean = x.head<2>();
  f.bias = x[2];
  f.covariance = p.topLeftCorner<2, 2>();
  f.bias_covariance = p.topRightCorner<2, 1>();
  f.bias_variance = p(2, 2);
  return correction;
}

kalman::Correction<3, 1> MotionModelBank::update_position(Filter& f, double z, double r) const {
  // kalman::update_covariance_student_t with H = [1 0], in scalars (a bank's members spend most
  // of their update in the general form's small matrices): S = P_pp + r, the noise scaled to r'
  // by the innovation's distance, k = P H^T / (P_pp + r'), and the Joseph form
  // P <- (I - k H) P (I - k H)^T + k r' k^T.
  kalman::Matrix<2>& p = f.covariance;
  const double innovation = z - f.mean[0];
  kalman::Correction<3, 1> out;
  out.innovation[0] = innovation;
  out.determinant = p(0, 0) + r;
  out.squared_distance = innovation * innovation / out.determinant;
  out.log_likelihood = std::numeric_limits<double>::quiet_NaN();  // read with the others'
  const double scaled = r * kalman::student_t_noise_scale(noise_model_, out.squared_distance, 1);
  const double k0 = p(0, 0) / (p(0, 0) + scaled), k1 = p(0, 1) / (p(0, 0) + scaled);
  const double keep = 1.0 - k0;  // (I - k H) = [keep 0; -k1 1]
  const double pp = keep * keep * p(0, 0) + k0 * k0 * scaled;
  const double pv = keep * (p(0, 1) - k1 * p(0, 0)) + k0 * k1 * scaled;
  const double vv = p(1, 1) - 2.0 * k1 * p(0, 1) + k1 * k1 * (p(0, 0) + scaled);
  p << pp, pv, pv, vv;
  out.correction << k0 * innovation, k1 * innovation, 0.0;
  f.mean += out.correction.head<2>();
  return out;
}

PartialViewBias MotionModelBank::partial_view_bias() const {
  PartialViewBias out{Eigen::Vector3d::Zero(), 0.0};
  for (int axis = 0; axis < 3; ++axis) {
    const std::span<const double> w = weights(axis);
    for (std::size_t j = 0; j < w.size(); ++j) out.mean[axis] += w[j] * filters_[axis][j].bias;
    for (std::size_t j = 0; j < w.size(); ++j) {
      const double d = filters_[axis][j].bias - out.mean[axis];
      out.variance += w[j] * (filters_[axis][j].bias_variance + d * d) / 3.0;
    }
  }
  return out;
}

void MotionModelBank::end_partial_views() {
  for (std::vector<Filter>& axis : filters_)
    for (Filter& f : axis) f.forget_bias();
  in_partial_views_ = false;
}

void MotionModelBank::start(Filter& filter, MotionModel model, double position, double previous,
                            double dt, double r) const {
  filter.surprises = 0;
  filter.forget_bias();
  if (model == MotionModel::kConstantPosition) {
    filter.mean << position, 0.0;
    filter.covariance << r, 0.0, 0.0, 0.0;
  } else if (dt > 0.0) {  // p = z2, v = (z2 - z1) / dt: var p = r, cov = r / dt, var v = 2 r / dt^2
    filter.mean << position, (position - previous) / dt;
    filter.covariance << r, r / dt, r / dt, 2.0 * r / (dt * dt);
  } else {  // the first measurement, or two at one time, carry no velocity: the prior's
    const double v = options_.initial_velocity_std;
    filter.mean << position, 0.0;
    filter.covariance << r, 0.0, 0.0, v * v;
  }
}

MemberPrediction MotionModelBank::member_prediction(int axis, std::size_t index,
                                                    double horizon) const {
  check_axis(axis);
  if (index >= models_[axis].size())
    throw std::out_of_range("MotionModelBank: no member " + std::to_string(index) + " on axis " +
                            std::to_string(axis));
  if (!initialised_) throw std::logic_error("MotionModelBank: predict() before any update()");
  if (!(horizon >= 0.0) || !std::isfinite(horizon))
    throw std::invalid_argument("MotionModelBank: the horizon must be a finite number >= 0 (s)");
  if (std::abs(horizon - steps_dt_) <= kSameInterval)
    return predicted_member(axis, index, steps_[shape_of_[axis][index]]);
  return predicted_member(axis, index, models_[axis][index].step(horizon));
}

const std::vector<AxisMotionStep>& MotionModelBank::steps_at(
    double dt, std::vector<AxisMotionStep>& scratch) const {
  if (std::abs(dt - steps_dt_) <= kSameInterval) return steps_;
  steps_over(shapes_, dt, scratch);
  return scratch;
}

MemberPrediction MotionModelBank::predicted_member(int axis, std::size_t index,
                                                   const AxisMotionStep& step) const {
  const Filter& f = filters_[axis][index];
  const double mean = (step.transition.row(0) * f.mean)(0, 0) + step.offset[0];
  const double variance =
      (step.transition.row(0) * f.covariance * step.transition.row(0).transpose())(0, 0) +
      step.process_noise(0, 0);
  return {model_name(models_[axis][index].model), weights_[axis].weights()[index], mean, variance};
}

BankPrediction MotionModelBank::predict(double horizon) const {
  BankPrediction out;
  predict(horizon, out);
  return out;
}

void MotionModelBank::predict(double horizon, BankPrediction& out) const {
  if (!initialised_) throw std::logic_error("MotionModelBank: predict() before any update()");
  if (!(horizon >= 0.0) || !std::isfinite(horizon))
    throw std::invalid_argument("MotionModelBank: the horizon must be a finite number >= 0 (s)");
  std::vector<AxisMotionStep> scratch;
  const std::vector<AxisMotionStep>& steps = steps_at(horizon, scratch);
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<MemberPrediction>& members = out.axes[static_cast<std::size_t>(axis)].members;
    members.resize(models_[axis].size());
    for (std::size_t j = 0; j < members.size(); ++j)
      members[j] = predicted_member(axis, j, steps[shape_of_[axis][j]]);
  }
}

Eigen::Vector3d MotionModelBank::variance_growth(double horizon) const {
  if (!initialised_) throw std::logic_error("MotionModelBank: predict() before any update()");
  std::vector<AxisMotionStep> scratch;
  const std::vector<AxisMotionStep>& steps = steps_at(horizon, scratch);
  Eigen::Vector3d growth;
  for (int axis = 0; axis < 3; ++axis) {
    // Moments about the first member's position: far from the origin, squares of positions
    // would cancel the variances' digits.
    const double reference = filters_[axis][0].mean[0];
    const std::span<const double> w = weights(axis);
    double mean_now = 0.0, square_now = 0.0, mean_ahead = 0.0, square_ahead = 0.0;
    for (std::size_t j = 0; j < filters_[axis].size(); ++j) {
      const Filter& f = filters_[axis][j];
      const MemberPrediction member = predicted_member(axis, j, steps[shape_of_[axis][j]]);
      const double now = f.mean[0] - reference;
      const double ahead = member.mean - reference;
      mean_now += w[j] * now;
      square_now += w[j] * (f.covariance(0, 0) + now * now);
      mean_ahead += w[j] * ahead;
      square_ahead += w[j] * (member.variance + ahead * ahead);
    }
    growth[axis] = (square_ahead - mean_ahead * mean_ahead) - (square_now - mean_now * mean_now);
  }
  return growth;
}

Eigen::Vector3d MotionModelBank::velocity() const {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < 3; ++axis) {
    const std::span<const double> w = weights(axis);
    for (std::size_t j = 0; j < filters_[axis].size(); ++j)
      v[axis] += w[j] * filters_[axis][j].mean[1];
  }
  return v;
}

double MotionModelBank::model_weight(int axis, MotionModel model) const {
  check_axis(axis);
  double sum = 0.0;
  for (std::size_t j = 0; j < models_[axis].size(); ++j)
    if (models_[axis][j].model == model) sum += weights_[axis].weights()[j];
  return sum;
}

std::size_t MotionModelBank::sample_member(int axis, double uniform01) const {
  check_axis(axis);
  return weighted_choice(weights_[axis].weights(), uniform01);
}

}  // namespace opf
