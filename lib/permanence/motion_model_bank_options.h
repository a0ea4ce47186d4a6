#pragma once
// Options of the motion-model bank (motion_model_bank.h). Its members' intensities are not
// options: each model runs at a stated grid of intensities (motion_model_bank.h), and the data
// weigh them; `intensity_scale` only moves the whole grid (another unit or scene scale).

#include "opf/core/option_schema.h"

#include <Eigen/Core>

#include <array>
#include <stdexcept>

namespace opf {

/// The degrees of freedom of the detector's noise as both motion-model banks model it: Student-t
/// with 1 (Cauchy). Detections have heavy tails (a partly covered object's centroid, a wrong
/// detection), and one the Gaussian would take at face value, a Cauchy likelihood discounts
/// (kalman::update_covariance_student_t), in the members' states and in their weights alike.
inline constexpr double kBankNoiseDof = 1.0;
/// A member that finds this many measurements in a row outside its 99.9% gate (chi-square on the
/// squared innovation over its Gaussian variance) has lost the object: its heavy-tailed likelihood
/// would read every later one as an outlier and never follow. It restarts from the last two
/// measurements (two-point differencing: position measured, velocity their slope), keeping its
/// weight; a single outlier does not restart it.
inline constexpr int kSurprisesToRestart = 2;
/// The rotation members' gate: the chi-square 99.9% quantile with 3 degrees of freedom.
inline constexpr double kRotationGateChiSquare = 16.266;
/// Both banks' intensity grid: the factors on each model's base density.
inline constexpr std::array<double, 3> kBankIntensityFactors = {0.1, 1.0, 10.0};
/// Both banks' damped models' time constants T (s): a push that dies within a gap (0.3 s) to a
/// glide (3 s).
inline constexpr std::array<double, 3> kBankDampingTimeConstants = {0.3, 1.0, 3.0};

struct MotionModelBankOptions {
  /// The models the bank holds (each at its intensity grid); at least one.
  bool constant_position = true;
  bool constant_velocity = true;
  bool damped_velocity = true;
  bool ballistic = true;
  /// The weights' memory T_memory (s): a member's past log-likelihood counts with the factor
  /// exp(-age / T_memory), whatever the frame rate.
  double memory = 1.0;
  /// The position measurement's noise standard deviation per axis (m): R = sigma^2.
  double observation_noise = 0.01;
  /// Up, a non-zero vector (normalised): gravity is -9.81 up m/s^2 (the ballistic model).
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  /// Every member's white-noise density is its grid value times this (no unit).
  double intensity_scale = 1.0;
  /// The prior standard deviation of the (unknown) velocity at the first position (m/s).
  double initial_velocity_std = 1.0;
};

/// The settings' `motion_model_bank:` section (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, MotionModelBankOptions& o) {
  v.section("models", [&] {
    v.flag("constant_position", o.constant_position);
    v.flag("constant_velocity", o.constant_velocity);
    v.flag("damped_velocity", o.damped_velocity);
    v.flag("ballistic", o.ballistic);
  });
  v.number("memory", o.memory, positive("a positive number (s)"));
  v.number("observation_noise", o.observation_noise, positive("a positive number (m)"));
  v.vector3("up", o.up);
  v.number("intensity_scale", o.intensity_scale, positive("a positive number (no unit)"));
  v.number("initial_velocity_std", o.initial_velocity_std, positive("a positive number (m/s)"));
}

/// Throws std::invalid_argument naming the first option out of range ("motion model bank option
/// memory must be a positive number (s), got 0"), or `models` if no model is included.
inline void validate(const MotionModelBankOptions& o) {
  check_options(o, "motion model bank");
  if (!o.constant_position && !o.constant_velocity && !o.damped_velocity && !o.ballistic)
    throw std::invalid_argument(
        "motion model bank option models must include at least one model, got none");
}

}  // namespace opf
