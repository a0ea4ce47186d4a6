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
  // axis in fixed-size storage (this runs dozens of times per occlusion onset). The powers of s
  // and the targets are computed once; the passes below only read them.
  const double span = std::max(t_ref - times[static_cast<std::size_t>(begin)], 1e-9);
  const auto n = static_cast<std::size_t>(count);
  std::vector<double> scratch(5 * n);
  const std::span<double> s1(scratch.data(), n), s2(scratch.data() + n, n);
  const std::span<double> y[3] = {std::span<double>(scratch.data() + 2 * n, n),
                                  std::span<double>(scratch.data() + 3 * n, n),
                                  std::span<double>(scratch.data() + 4 * n, n)};
  for (std::size_t i = 0; i < n; ++i) {
    const double t = times[static_cast<std::size_t>(begin) + i];
    const double s = (t - t_ref) / span;
    s1[i] = s;
    s2[i] = s * s;
    const double tau = t - t_ref;
    for (int axis = 0; axis < 3; ++axis)
      y[axis][i] = values(axis, begin + static_cast<Eigen::Index>(i)) -
                   0.5 * tau * tau * known_acceleration(axis);
  }
  // The basis (1, s, s^2) with the powers beyond the order zeroed; the normal matrix then gets an
  // identity block for them and their coefficients solve to zero, so every solve is a fixed 3 x 3.
  const double use1 = parameters > 1 ? 1.0 : 0.0, use2 = parameters > 2 ? 1.0 : 0.0;
  // The fit's value at sample i, summed as (c0 + s c1) + s^2 c2. Not through an Eigen::Vector3d
  // of the basis: its two scalar stores read back as one vector stall the store forwarding, and
  // made this the fit's dominant cost.
  const auto value_at = [&](std::size_t i, const Eigen::Vector3d& c) {
    return (c(0) + s1[i] * c(1)) + s2[i] * c(2);
  };
  // The weighted normal matrix's lower triangle (all the LDLT reads), entry (a, b) summed as
  // (w phi_a) phi_b (w = 1 where `w` is null), and the right-hand side per axis as (w y) phi_a.
  const auto normal_matrix = [&](const double* w) {
    double n00 = 0.0, n10 = 0.0, n11 = 0.0, n20 = 0.0, n21 = 0.0, n22 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double p1 = use1 * s1[i], p2 = use2 * s2[i];
      const double wi = w ? w[i] : 1.0;
      const double w1 = wi * p1, w2 = wi * p2;
      n00 += wi;
      n10 += w1;
      n11 += w1 * p1;
      n20 += w2;
      n21 += w2 * p1;
      n22 += w2 * p2;
    }
    Eigen::Matrix3d normal;
    normal << n00, 0.0, 0.0, n10, parameters > 1 ? n11 : 1.0, 0.0, n20, n21,
        parameters > 2 ? n22 : 1.0;
    return normal;
  };
  const auto right_hand_side = [&](const double* w, std::span<const double> target) {
    double r0 = 0.0, r1 = 0.0, r2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double wy = (w ? w[i] : 1.0) * target[i];
      r0 += wy;
      r1 += wy * (use1 * s1[i]);
      r2 += wy * (use2 * s2[i]);
    }
    return Eigen::Vector3d(r0, r1, r2);
  };

  // Unweighted, the normal matrix is the same for every axis.
  const Eigen::LDLT<Eigen::Matrix3d> unweighted(normal_matrix(nullptr));
  Eigen::Matrix3d solution = Eigen::Matrix3d::Zero();  // column per axis
  Eigen::Vector3d residual_variance = Eigen::Vector3d::Zero();
  if (robust_iterations == 0) {
    // Plain least squares.
    Eigen::Matrix3d rhs;
    for (int axis = 0; axis < 3; ++axis) rhs.col(axis) = right_hand_side(nullptr, y[axis]);
    solution = unweighted.solve(rhs);
    for (int axis = 0; axis < 3; ++axis) {
      for (std::size_t i = 0; i < n; ++i) {
        const double r = y[axis][i] - value_at(i, solution.col(axis));
        residual_variance(axis) += r * r;
      }
    }
  } else {
    // Each axis is reweighted on its own residuals: a large error on one axis (an unmodelled
    // fall) says nothing against the samples of another.
    std::vector<double> weights(n), magnitudes(n), sorted(n);
    for (int axis = 0; axis < 3; ++axis) {
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      bool weighted = false;  // all weights 1 until the first reweighting
      for (int iteration = 0;; ++iteration) {
        x = weighted ? normal_matrix(weights.data())
                           .ldlt()
                           .solve(right_hand_side(weights.data(), y[axis]))
                     : unweighted.solve(right_hand_side(nullptr, y[axis]));
        for (std::size_t i = 0; i < n; ++i) magnitudes[i] = std::abs(y[axis][i] - value_at(i, x));
        if (iteration >= robust_iterations) break;
        std::copy(magnitudes.begin(), magnitudes.end(), sorted.begin());
        const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(n / 2);
        std::nth_element(sorted.begin(), middle, sorted.end());
        const double scale = 1.4826 * *middle;
        if (!(scale > 0.0)) break;  // an exact fit: nothing to down-weight
        for (std::size_t i = 0; i < n; ++i)
          weights[i] = magnitudes[i] <= kHuberThreshold * scale
                           ? 1.0
                           : kHuberThreshold * scale / magnitudes[i];
        weighted = true;
      }
      solution.col(axis) = x;
      double sum = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        sum += (weighted ? weights[i] : 1.0) * magnitudes[i] * magnitudes[i];
      residual_variance(axis) = sum;
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
