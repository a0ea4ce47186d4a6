#pragma once
// Options of the rotation-model bank (rotation_model_bank.h); as for the translation bank, the
// members' intensities are a stated grid, moved as a whole by `intensity_scale`.

#include "opf/core/option_schema.h"

#include <stdexcept>

namespace opf {

struct RotationModelBankOptions {
  /// The models the bank holds (each at its intensity grid); at least one.
  bool constant_orientation = true;
  bool constant_angular_velocity = true;
  bool damped_angular_velocity = true;
  /// The weights' memory T_memory (s), as the translation bank's.
  double memory = 1.0;
  /// The measured orientation's noise standard deviation per tangent axis (rad).
  double observation_noise = 0.05;
  /// Every member's white-noise density is its grid value times this (no unit).
  double intensity_scale = 1.0;
  /// The prior standard deviation of the (unknown) angular velocity per axis (rad/s).
  double initial_angular_velocity_std = 1.0;
};

/// The settings' `rotation_model_bank:` section (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, RotationModelBankOptions& o) {
  v.section("models", [&] {
    v.flag("constant_orientation", o.constant_orientation);
    v.flag("constant_angular_velocity", o.constant_angular_velocity);
    v.flag("damped_angular_velocity", o.damped_angular_velocity);
  });
  v.number("memory", o.memory, positive("a positive number (s)"));
  v.number("observation_noise", o.observation_noise, positive("a positive number (rad)"));
  v.number("intensity_scale", o.intensity_scale, positive("a positive number (no unit)"));
  v.number("initial_angular_velocity_std", o.initial_angular_velocity_std,
           positive("a positive number (rad/s)"));
}

/// Throws std::invalid_argument naming the first option out of range.
inline void validate(const RotationModelBankOptions& o) {
  check_options(o, "rotation model bank");
  if (!o.constant_orientation && !o.constant_angular_velocity && !o.damped_angular_velocity)
    throw std::invalid_argument(
        "rotation model bank option models must include at least one model, got none");
}

}  // namespace opf
