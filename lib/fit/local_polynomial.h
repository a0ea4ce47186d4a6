#pragma once
// A local polynomial fit of a 3-vector signal in time (a position, or an unwrapped rotation
// vector), by robust weighted least squares: the building block of the dynamics module's model
// choice, which fits dozens of candidates at each occlusion onset. Closed form (normal equations
// of at most 3 x 3 per axis, Huber reweighting), so a candidate costs microseconds; the paper's
// Ceres fit (fit/trajectory_fit.h) stays for the `paper` predictor.

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <span>

namespace opf {

/// v(t) = c0 + c1 tau + c2 tau^2 + 1/2 a tau^2 with tau = t - t_ref, where a is a KNOWN
/// acceleration (gravity for the ballistic model, zero otherwise) and the c_k up to `order` are
/// fitted.
struct LocalPolynomial {
  double t_ref = 0.0;
  int order = 0;  ///< 0 constant, 1 constant rate, 2 constant second derivative
  Eigen::Matrix3d coefficients = Eigen::Matrix3d::Zero();  ///< column k: c_k; zero beyond order
  Eigen::Vector3d known_acceleration = Eigen::Vector3d::Zero();
  /// Per axis: the robust (weighted) mean squared residual of the fit.
  Eigen::Vector3d residual_variance = Eigen::Vector3d::Zero();
  int samples = 0;

  Eigen::Vector3d value(double t) const;
  Eigen::Vector3d rate(double t) const;  ///< dv/dt
};

/// Fits `order` (0..2) to the samples (times[i], values.col(i)) with times[i] in [t_from, t_ref],
/// expanded about t_ref, each axis on its own. Residuals beyond 1.345 robust sigmas (1.4826 MAD of
/// the axis's residuals) are down-weighted (Huber, `robust_iterations` reweightings; 0: plain least
/// squares). Returns false, leaving `fit` unspecified, when fewer than order + 2 samples lie in the
/// range (a fit needs a residual to say how good it is).
bool fit_local_polynomial(std::span<const double> times, const Eigen::Matrix3Xd& values,
                          double t_from, double t_ref, int order,
                          const Eigen::Vector3d& known_acceleration, int robust_iterations,
                          LocalPolynomial& fit);

}  // namespace opf
