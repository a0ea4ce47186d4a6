#pragma once
// The linear-Gaussian Kalman filter's two steps, shared by every Kalman estimator (cvkf, imm) and
// by anything else that propagates a Gaussian through a linear model: the prediction with a
// transition F and process noise Q, and the update with an observation matrix H, noise R and a
// measurement z, which also returns the innovation r = z - H x and its log-likelihood
// log N(r; 0, S), S = H P H^T + R (what an interacting-multiple-model filter weighs its models
// by). Fixed-size Eigen throughout: the sizes are template parameters, so the small products are
// unrolled. The kinematic models' discretisations that more than one filter uses live here too.

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <numbers>

namespace opf::kalman {

template <int N>
using Vector = Eigen::Matrix<double, N, 1>;
template <int Rows, int Cols = Rows>
using Matrix = Eigen::Matrix<double, Rows, Cols>;

/// The covariance half of a prediction, P <- F P F^T + Q: for error-state filters, whose mean
/// moves by its own nonlinear rule.
template <int N>
void predict_covariance(Matrix<N>& covariance, const Matrix<N>& transition,
                        const Matrix<N>& process_noise) {
  covariance = transition * covariance * transition.transpose() + process_noise;
}

/// x <- F x, P <- F P F^T + Q.
template <int N>
void predict(Vector<N>& mean, Matrix<N>& covariance, const Matrix<N>& transition,
             const Matrix<N>& process_noise) {
  mean = transition * mean;
  predict_covariance(covariance, transition, process_noise);
}

/// What an update did: the state correction K r it applied (an error-state filter injects it into
/// its own mean), the innovation r, its squared Mahalanobis distance d^2 = r^T S^-1 r and det S
/// under the S of the noise it was given (what a gate tests), and its log-likelihood.
template <int N, int M>
struct Correction {
  Vector<N> correction;
  Vector<M> innovation;
  double squared_distance = 0.0;
  double determinant = 0.0;
  double log_likelihood = 0.0;
};

namespace detail {

/// Solves with a symmetric positive-definite S and gives det S and log det S (each on demand): a
/// division when S is 1 x 1 (a bank's per-axis update), an LDLT factorisation above.
template <int M>
class SymmetricSolver {
 public:
  explicit SymmetricSolver(const Matrix<M>& s) {
    if constexpr (M == 1) {
      value_ = s(0, 0);
      inverse_ = 1.0 / value_;
    } else {
      ldlt_.compute(s);
    }
  }
  template <int Cols>
  Matrix<M, Cols> solve(const Matrix<M, Cols>& b) const {
    if constexpr (M == 1)
      return inverse_ * b;
    else
      return ldlt_.solve(b);
  }
  double determinant() const {
    if constexpr (M == 1)
      return value_;
    else
      return ldlt_.vectorD().prod();  // det S = prod D of S = L D L^T
  }
  double log_det() const {
    if constexpr (M == 1)
      return std::log(value_);
    else
      return ldlt_.vectorD().array().log().sum();
  }

 private:
  Eigen::LDLT<Matrix<M>> ldlt_;
  double value_ = 0.0;
  double inverse_ = 0.0;
};

/// P <- (I - K H) P (I - K H)^T + K R K^T, symmetrised, with K = P H^T S^-1 solved as
/// S K^T = H P (P and S symmetric); returns K r.
template <int N, int M>
Vector<N> joseph_update(Matrix<N>& covariance, const Matrix<M, N>& observation,
                        const Matrix<M>& noise, const Matrix<M, N>& hp, const SymmetricSolver<M>& s,
                        const Vector<M>& innovation) {
  const Matrix<N, M> gain = s.solve(hp).transpose();
  Matrix<N> a = Matrix<N>::Identity();
  a -= gain * observation;
  covariance = a * covariance * a.transpose() + gain * noise * gain.transpose();
  covariance = 0.5 * (covariance + covariance.transpose()).eval();
  return gain * innovation;
}

}  // namespace detail

/// log N(r; 0, S) in `dimensions` dimensions from d^2 = r^T S^-1 r and log det S:
/// -(d^2 + log det S + M log 2 pi) / 2.
inline double gaussian_log_density(double squared_distance, double log_det, int dimensions) {
  return -0.5 * (squared_distance + log_det + dimensions * std::log(2.0 * std::numbers::pi));
}

/// The update for a given innovation r (z - H x for a linear filter, a tangent-space difference
/// for an error-state one): P <- (I - K H) P (I - K H)^T + K R K^T, symmetrised. The Joseph form
/// keeps P symmetric positive definite under rounding, which the short form (I - K H) P does not
/// once the gain is large. Returns K r without applying it, and log N(r; 0, S). S must be positive
/// definite (R is).
template <int N, int M>
Correction<N, M> update_covariance(Matrix<N>& covariance, const Matrix<M, N>& observation,
                                   const Matrix<M>& noise, const Vector<M>& innovation) {
  const Matrix<M, N> hp = observation * covariance;
  const detail::SymmetricSolver<M> s(hp * observation.transpose() + noise);
  Correction<N, M> out;
  out.innovation = innovation;
  out.squared_distance = innovation.dot(s.solve(innovation));
  out.determinant = s.determinant();
  out.log_likelihood = gaussian_log_density(out.squared_distance, s.log_det(), M);
  out.correction = detail::joseph_update(covariance, observation, noise, hp, s, innovation);
  return out;
}

/// Student-t measurement noise in M dimensions with `dof` degrees of freedom, and the constant of
/// its log-density, log Gamma((dof + M) / 2) - log Gamma(dof / 2) - M / 2 log(dof pi), computed
/// once.
struct StudentTNoise {
  double dof = 1.0;
  double log_normaliser = 0.0;
};

template <int M>
StudentTNoise student_t_noise(double dof) {
  return {dof, std::lgamma((dof + M) / 2.0) - std::lgamma(dof / 2.0) -
                   0.5 * M * std::log(dof * std::numbers::pi)};
}

/// log t_dof(r; 0, S) in `dimensions` dimensions (those `t` was made for) from d^2 = r^T S^-1 r
/// and log det S.
inline double student_t_log_density(const StudentTNoise& t, double squared_distance, double log_det,
                                    int dimensions) {
  return t.log_normaliser - 0.5 * log_det -
         0.5 * (t.dof + dimensions) * std::log1p(squared_distance / t.dof);
}

/// The factor on R of the variational-Bayes step below: the inverse of w's posterior mean,
/// (dof + d^2) / (dof + M).
inline double student_t_noise_scale(const StudentTNoise& t, double squared_distance,
                                    int dimensions) {
  return (t.dof + squared_distance) / (t.dof + dimensions);
}

/// The update under Student-t measurement noise, a Gaussian scale mixture: the noise is
/// N(0, R / w) with w ~ Gamma(dof / 2, dof / 2). Given the innovation, w's posterior mean is
/// (dof + M) / (dof + d^2), d^2 = r^T S^-1 r (one variational-Bayes step of Agamennoni, Nieto &
/// Nebot, "Approximate inference in state-space models with heavy-tailed noise", IEEE Trans.
/// Signal Processing 60(10), 2012), so the update is update_covariance's with R scaled by its
/// inverse: a measurement far from the prediction moves the state less. d^2 and det S are under
/// the unscaled S. The log-likelihood, log t_dof(r; 0, S) = student_t_log_density(t, d^2,
/// log det S, M), is left to the caller (NaN here): a bank reads all its members' at once
/// (particles/student_t_densities.h).
template <int N, int M>
Correction<N, M> update_covariance_student_t(Matrix<N>& covariance, const Matrix<M, N>& observation,
                                             const Matrix<M>& noise, const Vector<M>& innovation,
                                             const StudentTNoise& t) {
  const Matrix<M, N> hp = observation * covariance;
  const Matrix<M> hpht = hp * observation.transpose();
  const detail::SymmetricSolver<M> s(hpht + noise);
  Correction<N, M> out;
  out.innovation = innovation;
  out.squared_distance = innovation.dot(s.solve(innovation));
  out.determinant = s.determinant();
  out.log_likelihood = std::numeric_limits<double>::quiet_NaN();
  const Matrix<M> scaled = noise * student_t_noise_scale(t, out.squared_distance, M);
  const detail::SymmetricSolver<M> s_scaled(hpht + scaled);
  out.correction = detail::joseph_update(covariance, observation, scaled, hp, s_scaled, innovation);
  return out;
}

/// The linear update with measurement z: r = z - H x, x <- x + K r, and P as update_covariance.
template <int N, int M>
Correction<N, M> update(Vector<N>& mean, Matrix<N>& covariance, const Matrix<M, N>& observation,
                        const Matrix<M>& noise, const Vector<M>& measurement) {
  const Vector<M> innovation = measurement - observation * mean;
  Correction<N, M> out = update_covariance(covariance, observation, noise, innovation);
  mean += out.correction;
  return out;
}

/// The exact discretisation over dt of continuous white-noise acceleration of density q (per
/// axis, units of the value / s^2 / sqrt(Hz)) for a 3-D (value, rate) state ordered
/// (value x, y, z, rate x, y, z): the covariance the pair accumulates while the rate random-walks.
Matrix<6> white_noise_acceleration(double q, double dt);

/// The transition of that state over dt: value <- value_block value + dt rate, rate kept.
Matrix<6> constant_rate_transition(const Eigen::Matrix3d& value_block, double dt);

/// A linear model's transition and process noise over one step.
template <int N>
struct LinearModel {
  Matrix<N> transition;
  Matrix<N> process_noise;
};

/// One axis's kinematic models over the state (position, velocity, acceleration), exactly
/// discretised over dt; the states a model does not have are held at zero (their rows of F and
/// Q zero), so models of different orders share the state (an interacting-multiple-model bank).
/// Constant position: the position random-walks, white velocity of density q (m/s/sqrt(Hz)).
LinearModel<3> constant_position_model(double q, double dt);
/// Constant velocity: white-noise acceleration of density q (m/s^2/sqrt(Hz)).
LinearModel<3> constant_velocity_model(double q, double dt);
/// Constant acceleration: Wiener-process acceleration, white jerk of density q (m/s^3/sqrt(Hz)).
LinearModel<3> constant_acceleration_model(double q, double dt);

}  // namespace opf::kalman
