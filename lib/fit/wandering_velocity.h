#pragma once
// A constant-velocity Kalman filter run along a sampled 3-vector signal, each axis on its own: the
// constant-velocity baseline's model as one of the dynamics module's candidates. Its memory (how
// far back the velocity estimate reaches) is set by the random acceleration's intensity against
// the measurement noise, which the dynamics module reads from the history itself.

#include "opf/fit/local_polynomial.h"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace opf {

/// The filter's state after one sample: position and velocity as an order-1 polynomial about the
/// sample's time, and the velocity's variance per axis.
struct WanderingVelocityState {
  LocalPolynomial line;
  Eigen::Vector3d rate_variance = Eigen::Vector3d::Zero();
};

/// The state after every sample (times[i], values.col(i)), i >= 1, started from the first two
/// samples (the first entry holds the first sample at zero velocity). `noise`: each axis's
/// measurement noise variance; `acceleration_intensity`: its random acceleration's intensity q
/// (m^2/s^3: the velocity's variance grows by q per second). Both are floored at 1e-12, so a
/// noise-free or a perfectly steady series still gives a finite filter. Throws
/// std::invalid_argument for fewer than two samples, a value count that is not the time count, or
/// times that do not increase.
std::vector<WanderingVelocityState> wandering_velocity_filter(
    std::span<const double> times, const Eigen::Matrix3Xd& values, const Eigen::Vector3d& noise,
    const Eigen::Vector3d& acceleration_intensity);

}  // namespace opf
