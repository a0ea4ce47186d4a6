#pragma once
// Options of the constant-velocity Kalman filter baseline.

#include "opf/core/option_schema.h"

namespace opf {

struct CvKalmanOptions {
  /// White-noise acceleration densities (continuous-time, per axis): m/s^2/sqrt(Hz) and
  /// rad/s^2/sqrt(Hz). They set how fast the covariance grows while predicting through a gap.
  double acceleration_noise = 0.5;
  double angular_acceleration_noise = 1.0;
  /// Observation noise standard deviation per axis, m and rad (tangent space).
  double observation_noise_translation = 0.01;
  double observation_noise_rotation = 0.05;
  /// Prior standard deviation of the (unknown) velocities at the first detection.
  double initial_velocity_std = 0.5;
  double initial_angular_velocity_std = 1.0;
};

/// The settings file's `cvkf:` section (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, CvKalmanOptions& o) {
  v.number("acceleration_noise", o.acceleration_noise,
           noise_scale("a positive number (m/s^2/sqrt(Hz)) up to 1e6"));
  v.number("angular_acceleration_noise", o.angular_acceleration_noise,
           noise_scale("a positive number (rad/s^2/sqrt(Hz)) up to 1e6"));
  describe_observation_noise(v, o.observation_noise_translation, o.observation_noise_rotation);
  v.number("initial_velocity_std", o.initial_velocity_std,
           noise_scale("a positive number (m/s) up to 1e6"));
  v.number("initial_angular_velocity_std", o.initial_angular_velocity_std,
           noise_scale("a positive number (rad/s) up to 1e6"));
}

}  // namespace opf
