#pragma once
// A bank of orientation models (tangent_rotation_filter.h), combined by Bayesian model averaging
// with forgetting in continuous time (model_weights.h), as the translation bank
// (motion_model_bank.h) but over the whole rotation (its tangent axes are coupled by the
// rotation, so one weight per member, not per axis). The members (each density times
// options.intensity_scale):
//   constant orientation       q in {0.003, 0.03, 0.3} rad/s/sqrt(Hz)     (0.1, 1, 10 x 0.03)
//   constant angular velocity  q in {0.1, 1, 10} rad/s^2/sqrt(Hz)         (0.1, 1, 10 x 1)
//   damped angular velocity    q as constant angular velocity, x T in {0.3, 1, 3} s
// The bases: an object at rest, held or on a table, wanders by a few hundredths of a radian a
// second; a turning one changes its rate by about 1 rad/s within a second; a turn of the wrist
// dies away within a gap (0.3 s), a tossed object's spin glides (3 s), as the translation bank's
// damped model. Each model has the prior 1 / (number of models), shared equally by its members.

#include "opf/motion/tangent_rotation_filter.h"
#include "opf/permanence/model_weights.h"
#include "opf/permanence/motion_model_bank_options.h"
#include "opf/permanence/rotation_model_bank_options.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <span>
#include <string_view>
#include <vector>

namespace opf {

/// Constant orientation's base angular-velocity density (rad/s/sqrt(Hz)).
inline constexpr double kRotationBankOrientationNoiseBase = 0.03;
/// Constant angular velocity's base angular-acceleration density (rad/s^2/sqrt(Hz)).
inline constexpr double kRotationBankAngularAccelerationNoiseBase = 1.0;

/// One member's predicted orientation and tangent covariance (rad^2) there, with its weight.
struct RotationMemberPrediction {
  std::string_view model;  ///< rotation_model_name() of the member's model
  double weight = 0.0;
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};

class RotationModelBank {
 public:
  /// Throws std::invalid_argument naming the first bad option.
  explicit RotationModelBank(const RotationModelBankOptions& options = {});

  /// A measured orientation at time t (s), not before the last one. The first starts every
  /// member (orientation measured, rate 0 with options.initial_angular_velocity_std); a later one
  /// steps and updates every member and the weights.
  void update(double t, const Eigen::Quaterniond& orientation);

  bool initialised() const { return initialised_; }

  /// The mixture's mean body-frame angular velocity (rad/s) at the last update.
  Eigen::Vector3d angular_velocity() const;
  /// Every member's prediction `horizon` s (>= 0) after the last update.
  std::vector<RotationMemberPrediction> predict(double horizon) const;
  /// The same into `out`, resized.
  void predict(double horizon, std::vector<RotationMemberPrediction>& out) const;
  /// How much the members' orientation variance grows over `horizon` s, per tangent axis
  /// (rad^2): sum_k w_k [tr C_k(horizon) - tr C_k(0)] / 3.
  double variance_growth(double horizon) const;
  RotationMemberPrediction member_prediction(std::size_t index, double horizon) const;

  std::span<const TangentRotationFilter> members() const { return filters_; }
  std::span<const double> weights() const { return weights_.weights(); }
  double model_weight(RotationModel model) const;
  /// The member a uniform draw in [0, 1) maps to, by weight (weighted_choice.h).
  std::size_t sample_member(double uniform01) const;

  const RotationModelBankOptions& options() const { return options_; }

 private:
  /// Every member's step over dt (the cached ones at the last update's interval).
  const std::vector<AxisMotionStep>& steps_at(double dt,
                                              std::vector<AxisMotionStep>& scratch) const;

  RotationModelBankOptions options_;
  std::vector<TangentRotationFilter> filters_;
  /// Each member's per-axis model, and their steps over the last update's interval, computed
  /// together (steps_over) and reused while frames keep one rate.
  std::vector<AxisMotionModel> axis_models_;
  double steps_dt_ = -1.0;
  std::vector<AxisMotionStep> steps_;
  std::vector<int> surprises_;  ///< per member: consecutive measurements outside its gate
  Eigen::Quaterniond last_orientation_ = Eigen::Quaterniond::Identity();
  ModelWeights weights_;
  /// Scratch per member: det S, d^2, then their log-densities.
  std::vector<double> determinants_, squared_distances_, log_likelihoods_;
  /// The detector's noise in the tangent space (kBankNoiseDof).
  kalman::StudentTNoise noise_model_ = kalman::student_t_noise<3>(kBankNoiseDof);
  double t_ = 0.0;
  bool initialised_ = false;
};

}  // namespace opf
