#include "opf/fit/local_polynomial.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

constexpr double kHuberThreshold = 1.345;  // sigmas: 95% efficiency under Gaussian noise
constexpr int kMaxOrder = 2;

}  // namespace

Eigen::Vector3d LocalPolynomial::value(double t) const {
  const double tau = t - t_ref;
  return coefficients.col(0) + tau * (coefficients.col(1) + tau * coefficients.col(2)) +
         0.5 * tau * tau * known_acceleration;
}

Eigen::Vector3d LocalPolynomial::rate(double t) const {
  const double tau = t - t_ref;
  return coefficients.col(1) + 2.0 * tau * coefficients.col(2) + tau * known_acceleration;
}

bool fit_local_polynomial(std::span<const double> times, const Eigen::Matrix3Xd& values,
                          double t_from, double t_ref, int order,
                          const Eigen::Vector3d& known_acceleration, int robust_iterations,
                          LocalPolynomial& fit) {
  if (order < 0 || order > kMaxOrder)
    throw std::invalid_argument("fit_local_polynomial: order must be 0, 1 or 2");
  if (static_cast<Eigen::Index>(times.size()) != values.cols())
    throw std::invalid_argument("fit_local_polynomial: one value per time needed");
  // The samples in range: times are sorted, so one contiguous run.
  const auto first = std::lower_bound(times.begin(), times.end(), t_from);
  const auto last = std::upper_bound(first, times.end(), t_ref);
  const auto begin = static_cast<Eigen::Index>(first - times.begin());
  const auto count = static_cast<Eigen::Index>(last - first);
  const int parameters = order + 1;
  if (count < parameters + 1) return false;

  // In s = tau / span, so the normal equations stay well conditioned; at most 3 x 3, solved per
  // axis in fixed-size storage (this runs dozens of times per occlusion onset).
  const double span = std::max(t_ref - times[static_cast<std::size_t>(begin)], 1e-9);
  const auto basis = [&](Eigen::Index i) {
    const double s = (times[static_cast<std::size_t>(begin + i)] - t_ref) / span;
    return Eigen::Vector3d(1.0, s, s * s);
  };
  const auto target = [&](Eigen::Index i, int axis) {
    const double tau = times[static_cast<std::size_t>(begin + i)] - t_ref;
    return values(axis, begin + i) - 0.5 * tau * tau * known_acceleration(axis);
  };

  Eigen::Matrix3d solution = Eigen::Matrix3d::Zero();  // column per axis
  Eigen::Vector3d residual_variance = Eigen::Vector3d::Zero();
  // The basis with the unused powers zeroed; the normal matrix then gets an identity block for
  // them and their coefficients solve to zero, so every solve is a fixed 3 x 3.
  const auto padded = [&](Eigen::Index i) {
    Eigen::Vector3d phi = basis(i);
    for (int k = parameters; k < 3; ++k) phi(k) = 0.0;
    return phi;
  };
  const auto pad = [&](Eigen::Matrix3d& normal) {
    for (int k = parameters; k < 3; ++k) normal(k, k) = 1.0;
  };

  if (robust_iterations == 0) {
    // Plain least squares: one normal matrix for the three axes, one pass.
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Matrix3d rhs = Eigen::Matrix3d::Zero();  // column per axis
    for (Eigen::Index i = 0; i < count; ++i) {
      const Eigen::Vector3d phi = padded(i);
      normal.noalias() += phi * phi.transpose();
      rhs.noalias() += phi * Eigen::RowVector3d(target(i, 0), target(i, 1), target(i, 2));
    }
    pad(normal);
    solution = normal.ldlt().solve(rhs);
    for (Eigen::Index i = 0; i < count; ++i) {
      const Eigen::Vector3d phi = padded(i);
      for (int axis = 0; axis < 3; ++axis) {
        const double r = target(i, axis) - phi.dot(solution.col(axis));
        residual_variance(axis) += r * r;
      }
    }
  } else {
    // Each axis is reweighted on its own residuals: a large error on one axis (an unmodelled
    // fall) says nothing against the samples of another.
    std::vector<double> weights(static_cast<std::size_t>(count));
    std::vector<double> magnitudes(static_cast<std::size_t>(count));
    std::vector<double> sorted(static_cast<std::size_t>(count));
    for (int axis = 0; axis < 3; ++axis) {
      std::fill(weights.begin(), weights.end(), 1.0);
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      for (int iteration = 0;; ++iteration) {
        Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
        Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
        for (Eigen::Index i = 0; i < count; ++i) {
          const Eigen::Vector3d phi = padded(i);
          const double w = weights[static_cast<std::size_t>(i)];
          normal.noalias() += w * phi * phi.transpose();
          rhs.noalias() += w * target(i, axis) * phi;
        }
        pad(normal);
        x = normal.ldlt().solve(rhs);
        for (Eigen::Index i = 0; i < count; ++i)
          magnitudes[static_cast<std::size_t>(i)] = std::abs(target(i, axis) - basis(i).dot(x));
        if (iteration >= robust_iterations) break;
        std::copy(magnitudes.begin(), magnitudes.end(), sorted.begin());
        const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
        std::nth_element(sorted.begin(), middle, sorted.end());
        const double scale = 1.4826 * *middle;
        if (!(scale > 0.0)) break;  // an exact fit: nothing to down-weight
        for (std::size_t i = 0; i < weights.size(); ++i)
          weights[i] = magnitudes[i] <= kHuberThreshold * scale
                           ? 1.0
                           : kHuberThreshold * scale / magnitudes[i];
      }
      solution.col(axis) = x;
      double weighted = 0.0;
      for (std::size_t i = 0; i < weights.size(); ++i)
        weighted += weights[i] * magnitudes[i] * magnitudes[i];
      residual_variance(axis) = weighted;
    }
  }

  fit.t_ref = t_ref;
  fit.order = order;
  fit.known_acceleration = known_acceleration;
  fit.coefficients.setZero();
  double power = 1.0;
  for (int k = 0; k < parameters; ++k, power *= span)
    fit.coefficients.col(k) = solution.row(k).transpose() / power;
  const double dof = static_cast<double>(count - parameters);
  fit.residual_variance = residual_variance / std::max(dof, 1.0);
  fit.samples = static_cast<int>(count);
  return true;
}

}  // namespace opf
