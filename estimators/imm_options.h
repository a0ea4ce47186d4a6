#pragma once
// Options of the interacting-multiple-model Kalman filter baseline (estimators/imm_kalman.h).

#include "opf/core/option_schema.h"

namespace opf {

struct ImmOptions {
  /// White-noise densities (continuous-time, per axis) of the three translation models:
  /// constant position, a random-walk position of velocity density q_cp (m/s/sqrt(Hz));
  double position_noise = 0.05;
  /// constant velocity, white-noise acceleration (m/s^2/sqrt(Hz)), cvkf's acceleration_noise;
  double acceleration_noise = 0.5;
  /// constant acceleration, Wiener-process acceleration of white jerk (m/s^3/sqrt(Hz)).
  double jerk_noise = 5.0;
  /// Mean sojourn time in a model (s): it is left at the rate 1/tau, to either other model
  /// equally; P(no switch over dt) = exp(-dt / tau), whatever the frame rate.
  double mean_sojourn = 2.0;
  /// The rotation, as cvkf's: white-noise angular acceleration (rad/s^2/sqrt(Hz)).
  double angular_acceleration_noise = 1.0;
  /// Observation noise standard deviation per axis, m and rad (tangent space).
  double observation_noise_translation = 0.01;
  double observation_noise_rotation = 0.05;
  /// Prior standard deviations of the (unknown) rates at the first detection.
  double initial_velocity_std = 0.5;
  double initial_acceleration_std = 2.0;
  double initial_angular_velocity_std = 1.0;
};

/// The settings file's `imm:` section (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, ImmOptions& o) {
  v.section("process_noise", [&] {
    v.number("position", o.position_noise,
             noise_scale("a positive number (m/s/sqrt(Hz)) up to 1e6"));
    v.number("acceleration", o.acceleration_noise,
             noise_scale("a positive number (m/s^2/sqrt(Hz)) up to 1e6"));
    v.number("jerk", o.jerk_noise, noise_scale("a positive number (m/s^3/sqrt(Hz)) up to 1e6"));
    v.number("angular_acceleration", o.angular_acceleration_noise,
             noise_scale("a positive number (rad/s^2/sqrt(Hz)) up to 1e6"));
  });
  v.number("mean_sojourn", o.mean_sojourn, positive("a positive number (s)"));
  describe_observation_noise(v, o.observation_noise_translation, o.observation_noise_rotation);
  v.number("initial_velocity_std", o.initial_velocity_std,
           noise_scale("a positive number (m/s) up to 1e6"));
  v.number("initial_acceleration_std", o.initial_acceleration_std,
           noise_scale("a positive number (m/s^2) up to 1e6"));
  v.number("initial_angular_velocity_std", o.initial_angular_velocity_std,
           noise_scale("a positive number (rad/s) up to 1e6"));
}

}  // namespace opf
