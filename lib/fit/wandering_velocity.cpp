#include "opf/fit/wandering_velocity.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace opf {

std::vector<WanderingVelocityState> wandering_velocity_filter(
    std::span<const double> times, const Eigen::Matrix3Xd& values, const Eigen::Vector3d& noise,
    const Eigen::Vector3d& acceleration_intensity) {
  const std::size_t n = times.size();
  if (n < 2 || values.cols() != static_cast<Eigen::Index>(n))
    throw std::invalid_argument(
        "wandering_velocity_filter: needs two samples or more, one per time");
  for (std::size_t k = 1; k < n; ++k)
    if (!(times[k] > times[k - 1]))
      throw std::invalid_argument("wandering_velocity_filter: times must increase");
  // The three axes side by side: each is its own two-state filter.
  using Axes = Eigen::Array3d;
  const Axes r = noise.array().max(1e-12);
  const Axes q = acceleration_intensity.array().max(1e-12);
  // Started from the first two samples: their difference is the velocity, with the variance two
  // noisy positions give it.
  const double dt0 = times[1] - times[0];
  Axes position = values.col(1).array();
  Axes velocity = (values.col(1) - values.col(0)).array() / dt0;
  Axes pp = r, pv = r / dt0, vv = 2.0 * r / (dt0 * dt0);
  std::vector<WanderingVelocityState> track(n);
  track[0].line.t_ref = times[0];
  track[0].line.order = 1;
  track[0].line.coefficients.col(0) = values.col(0);
  track[0].line.samples = 1;
  for (std::size_t k = 1; k < n; ++k) {
    if (k >= 2) {
      const double dt = times[k] - times[k - 1];
      // Predict under white random acceleration, then correct by the measurement.
      position += velocity * dt;
      const Axes predicted_pp = pp + 2.0 * dt * pv + dt * dt * vv + q * (dt * dt * dt / 3.0);
      const Axes predicted_pv = pv + dt * vv + q * (dt * dt / 2.0);
      const Axes predicted_vv = vv + q * dt;
      const Axes innovation_variance = predicted_pp + r;
      const Axes gain_p = predicted_pp / innovation_variance;
      const Axes gain_v = predicted_pv / innovation_variance;
      const Axes innovation = values.col(static_cast<Eigen::Index>(k)).array() - position;
      position += gain_p * innovation;
      velocity += gain_v * innovation;
      pp = (1.0 - gain_p) * predicted_pp;
      pv = (1.0 - gain_p) * predicted_pv;
      vv = predicted_vv - gain_v * predicted_pv;
    }
    WanderingVelocityState& state = track[k];
    state.line.t_ref = times[k];
    state.line.order = 1;
    state.line.coefficients.col(0) = position.matrix();
    state.line.coefficients.col(1) = velocity.matrix();
    state.line.residual_variance = r.matrix();
    state.line.samples = static_cast<int>(k + 1);
    state.rate_variance = vv.matrix();
  }
  return track;
}

}  // namespace opf
