#include "opf/estimators/cv_kalman.h"

#include "opf/core/metrics.h"
#include "opf/core/pose_conversion.h"
#include "opf/core/random.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>
#include <mrpt/math/CQuaternion.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace opf {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Gain = Eigen::Matrix<double, 6, 3>;

constexpr double kDt = 1.0 / 30.0;
// E||e|| = sqrt(8/pi) s ~ 1.596 s for e ~ N(0, s^2 I_3): the mean of a chi distribution, 3 dof.
const double kMeanNormFactor = std::sqrt(8.0 / std::numbers::pi);
// The 99.9 % quantile of chi^2_3 is 16.27: P(||e|| > 4.034 s) = 1e-3 for e ~ N(0, s^2 I_3), and
// at most that when s^2 is the largest eigenvalue of a non-isotropic covariance.
constexpr double kNormQuantile999 = 4.034;

Eigen::Vector3d normal3(Random& rng) {
  return {rng.normal(), rng.normal(), rng.normal()};
}

// The truth in most scenarios here has no acceleration at all, so they use process noise
// densities tenfold below the defaults: the velocity estimates then average over about a second,
// which is what makes extrapolating through a 1 s gap worthwhile.
CvKalmanOptions tracking_options() {
  CvKalmanOptions options;
  options.acceleration_noise = 0.05;
  options.angular_acceleration_noise = 0.1;
  return options;
}

// ---- Linear theory of the filter's model, rebuilt here from the definitions, not the source. ---

Matrix6 model_transition(const Eigen::Matrix3d& value_block) {
  Matrix6 f = Matrix6::Identity();
  f.topLeftCorner<3, 3>() = value_block;
  f.topRightCorner<3, 3>() = kDt * Eigen::Matrix3d::Identity();
  return f;
}

Matrix6 model_process_noise(double q) {
  const Eigen::Matrix3d i = q * q * Eigen::Matrix3d::Identity();
  Matrix6 noise;
  noise << kDt * kDt * kDt / 3.0 * i, kDt * kDt / 2.0 * i, kDt * kDt / 2.0 * i, kDt * i;
  return noise;
}

Gain kalman_gain(const Matrix6& prior, double variance) {
  return prior.leftCols<3>() *
         (prior.topLeftCorner<3, 3>() + variance * Eigen::Matrix3d::Identity()).inverse();
}

Matrix6 one_minus_kh(const Gain& gain) {
  Matrix6 a = Matrix6::Identity();
  a.leftCols<3>() -= gain;
  return a;
}

struct Theory {
  Matrix6 transition;
  Matrix6 process_noise;
  double variance;    ///< of the measurement, per axis
  Matrix6 posterior;  ///< the filter's own covariance after an update, at the Riccati fixed point
  /// The true error covariance after an update when the truth follows `transition` exactly (no
  /// acceleration at all), from e+ = (I - K H) F e+ + K v with the steady gain K: a Lyapunov
  /// equation. It is below `posterior`, as Q models accelerations that never happen.
  Matrix6 actual_error;
  /// Spectral radius of the closed loop (I - K H) F (a bound a few 1e-6 above it): how fast an
  /// initial error dies out.
  double closed_loop_radius;
};

// Gelfand's formula: rho(A) <= ||A^k||^(1/k) for every k, with equality as k grows; k = 2^20 by
// repeated squaring, each square rescaled to norm one (its log kept) so that nothing underflows.
// An upper bound, so `settled` below can only be stricter than with the exact radius.
double spectral_radius_bound(const Matrix6& a) {
  constexpr int kSquarings = 20;
  Matrix6 power = a;
  double log_norm = 0.0;  // log ||A^(2^i)|| = log_norm + log ||power||
  for (int i = 0; i < kSquarings; ++i) {
    power = power * power;  // Eigen evaluates a product into a temporary
    const double norm = power.norm();
    power /= norm;
    log_norm = 2.0 * log_norm + std::log(norm);
  }
  return std::exp(log_norm / std::ldexp(1.0, kSquarings));
}

Theory steady_state(const Matrix6& f, const Matrix6& q, double variance) {
  Matrix6 p = Matrix6::Identity();
  Gain gain;
  for (int i = 0; i < 20000; ++i) {
    const Matrix6 prior = f * p * f.transpose() + q;
    gain = kalman_gain(prior, variance);
    p = one_minus_kh(gain) * prior;
  }
  const Matrix6 closed_loop = one_minus_kh(gain) * f;
  Matrix6 e = p;
  for (int i = 0; i < 20000; ++i)
    e = closed_loop * e * closed_loop.transpose() + variance * gain * gain.transpose();
  return {f, q, variance, p, e, spectral_radius_bound(closed_loop)};
}

// After n frames an initial error has shrunk below n rho^n of its size (rho the closed loop's
// spectral radius, a double pole here); 1e-4 puts the transient of a start with zero velocity far
// below the steady error in every scenario of this file.
bool settled(const Theory& theory, int frames) {
  return frames * std::pow(theory.closed_loop_radius, frames) < 1e-4;
}

// The filter covariance P and the true error covariance E (truth without acceleration), frame by
// frame, from the steady state through `gap` frames without measurements and `after` frames with.
// Linear and exact for the translation; first order for the rotation.
struct GapTheory {
  std::vector<Matrix6> filter;
  std::vector<Matrix6> error;
};

GapTheory through_gap(const Theory& theory, int gap, int after) {
  const Matrix6& f = theory.transition;
  Matrix6 p = theory.posterior;
  Matrix6 e = theory.actual_error;
  GapTheory out;
  for (int k = 0; k < gap + after; ++k) {
    p = f * p * f.transpose() + theory.process_noise;
    e = f * e * f.transpose();
    if (k >= gap) {
      const Gain gain = kalman_gain(p, theory.variance);
      const Matrix6 a = one_minus_kh(gain);
      p = a * p;
      e = a * e * a.transpose() + theory.variance * gain * gain.transpose();
    }
    out.filter.push_back(p);
    out.error.push_back(e);
  }
  return out;
}

double largest_eigenvalue(const Eigen::Matrix3d& m) {
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m).eigenvalues().maxCoeff();
}

double relative_difference(double a, double b) {
  return std::abs(a - b) / std::abs(b);
}

// ---- Simulated tracks. ----

// A measurement with isotropic Gaussian noise: additive on the translation, in the right tangent
// space on the orientation (the filter's observation model).
mrpt::poses::CPose3D noisy(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                           const CvKalmanOptions& options, Random& rng) {
  const Eigen::Vector3d dp = options.observation_noise_translation * normal3(rng);
  const Eigen::Vector3d dtheta = options.observation_noise_rotation * normal3(rng);
  return make_pose(position + dp, orientation * so3::exp(dtheta));
}

const Frame kEmptyFrame{};
const EnsembleView kNoEnsemble{kEmptyFrame, {}};

struct Track {
  std::vector<Estimate> estimates;
  std::vector<mrpt::poses::CPose3D> truth;
  std::vector<double> raw_translation_errors;  ///< of the measurements; 0 where there is none
  int flipped_measurements = 0;  ///< measured quaternions on the other hemisphere from the truth's
};

struct Pose {
  Eigen::Vector3d position;
  Eigen::Quaterniond orientation;
};

// Runs a fresh filter over frames k = 0 .. frames-1 at 30 Hz; frames in [gap_begin, gap_end) carry
// no measurement.
template <typename TruthAt>
Track run(const CvKalmanOptions& options, std::uint64_t seed, int frames, int gap_begin,
          int gap_end, TruthAt truth_at) {
  ConstantVelocityKalman filter(options);
  Random rng(seed);
  Track track;
  for (int k = 0; k < frames; ++k) {
    const double t = k * kDt;
    const Pose truth = truth_at(t);
    track.truth.push_back(make_pose(truth.position, truth.orientation));
    const mrpt::poses::CPose3D z = noisy(truth.position, truth.orientation, options, rng);
    if (orientation_of(z).dot(truth.orientation) < 0.0) ++track.flipped_measurements;
    const bool measured = k < gap_begin || k >= gap_end;
    track.raw_translation_errors.push_back(measured ? translation_error(z, track.truth.back())
                                                    : 0.0);
    track.estimates.push_back(k == 0 ? filter.initialise(t, z)
                                     : filter.step(t, measured ? &z : nullptr, kNoEnsemble));
  }
  return track;
}

// A straight line at constant velocity (|v| = 0.54 m/s) and fixed orientation.
const Eigen::Vector3d kLineStart(1.0, -2.0, 0.5);
const Eigen::Vector3d kLineVelocity(0.4, -0.3, 0.2);
const Eigen::Quaterniond kLineOrientation = so3::exp(Eigen::Vector3d(0.2, -0.4, 1.1));

Track run_line(std::uint64_t seed, int frames, int gap_begin, int gap_end) {
  return run(tracking_options(), seed, frames, gap_begin, gap_end, [](double t) {
    return Pose{kLineStart + t * kLineVelocity, kLineOrientation};
  });
}

// A constant body rate |w| = 1.2 rad/s about a fixed axis, at a fixed position. It turns once
// every 5.2 s, so the measured quaternions (converted from rotation matrices) fall on both
// hemispheres relative to the continuously propagated truth.
const Eigen::Vector3d kPosition(0.3, 0.1, -0.7);
const Eigen::Quaterniond kStartOrientation = so3::exp(Eigen::Vector3d(-0.5, 0.9, 0.3));
const Eigen::Vector3d kRate = 1.2 * Eigen::Vector3d(0.3, -0.5, 0.8).normalized();

Track run_rotation(std::uint64_t seed, int frames, int gap_begin, int gap_end) {
  return run(tracking_options(), seed, frames, gap_begin, gap_end, [](double t) {
    // Fixed axis: the product of the per-frame exp(w dt) is exp(w t) exactly.
    return Pose{kPosition, kStartOrientation * so3::exp(t * kRate)};
  });
}

Theory line_theory() {
  const CvKalmanOptions options = tracking_options();
  const double sigma = options.observation_noise_translation;
  return steady_state(model_transition(Eigen::Matrix3d::Identity()),
                      model_process_noise(options.acceleration_noise), sigma * sigma);
}

// Body-frame constant rate: the linearised error transition is time-invariant, with the block
// Exp(-w dt) of the true rate (which the estimated rate converges to).
Theory rotation_theory() {
  const CvKalmanOptions options = tracking_options();
  const double sigma = options.observation_noise_rotation;
  return steady_state(model_transition(so3::exp(-kDt * kRate).toRotationMatrix()),
                      model_process_noise(options.angular_acceleration_noise), sigma * sigma);
}

double position_variance(const Estimate& estimate) {
  return estimate.pose.cov(0, 0);
}

// ---- Tests. ----

TEST(ConstantVelocityKalman, InitialisesAtTheFirstMeasurement) {
  CvKalmanOptions options;
  options.observation_noise_translation = 0.02;
  options.observation_noise_rotation = 0.03;
  ConstantVelocityKalman filter(options);
  EXPECT_EQ(filter.name(), "cvkf");

  const Eigen::Vector3d p(1.0, 2.0, 3.0);
  const Eigen::Quaterniond q = so3::exp(Eigen::Vector3d(0.3, -0.2, 0.9));
  const Estimate e = filter.initialise(4.5, make_pose(p, q));
  EXPECT_EQ(e.mode, EstimateMode::kMeasured);
  EXPECT_EQ(e.t, 4.5);
  EXPECT_LT(translation_error(e.pose.mean, make_pose(p, q)), 1e-12);
  EXPECT_LT(rotation_error_geodesic(e.pose.mean, make_pose(p, q)), 1e-9);
  const auto expected = make_pose_pdf(p, 0.02 * 0.02 * Eigen::Matrix3d::Identity(), q,
                                      0.03 * 0.03 * Eigen::Matrix3d::Identity());
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(e.pose.cov(r, c), expected.cov(r, c), 1e-12);
  EXPECT_DOUBLE_EQ(e.observation_trace, 3 * 0.02 * 0.02 + 3 * 0.03 * 0.03);
}

TEST(ConstantVelocityKalman, StraightLineErrorMatchesSteadyStateTheory) {
  const Theory theory = line_theory();
  const double sigma = tracking_options().observation_noise_translation;
  constexpr int kFrames = 900;  // 30 s
  constexpr int kBurnIn = 150;  // 5 s
  ASSERT_TRUE(settled(theory, kBurnIn));

  const Track track = run_line(11, kFrames, kFrames, kFrames);
  double filter_sum = 0.0, raw_sum = 0.0;
  for (int k = 0; k < kFrames; ++k) {
    EXPECT_EQ(track.estimates[k].mode, EstimateMode::kMeasured);
    EXPECT_DOUBLE_EQ(track.estimates[k].t, k * kDt);
    if (k < kBurnIn) continue;
    filter_sum += translation_error(track.estimates[k].pose.mean, track.truth[k]);
    raw_sum += track.raw_translation_errors[k];
  }
  const double filter_mean = filter_sum / (kFrames - kBurnIn);
  const double raw_mean = raw_sum / (kFrames - kBurnIn);

  // The reported covariance is the Riccati fixed point of the same model (deterministic: exact).
  EXPECT_LT(relative_difference(position_variance(track.estimates.back()), theory.posterior(0, 0)),
            1e-9);

  // Expected mean error: sqrt(8/pi) sqrt(E_xx), E the true steady error covariance (the axes are
  // identical and decoupled, so the error is isotropic). One frame's error norm has a relative
  // standard deviation of 0.42 (chi, 3 dof) and the errors are correlated over a few frames
  // (closed-loop radius 0.88), leaving ~150 effective samples of 750: 1 sigma is 3.4 % (which
  // 1000 seeds confirm: 0.998 +- 0.034). The band is 4 sigma.
  const double expected = kMeanNormFactor * std::sqrt(theory.actual_error(0, 0));
  EXPECT_GT(filter_mean, 0.86 * expected);
  EXPECT_LT(filter_mean, 1.14 * expected);
  // The filter is conservative for a truth without acceleration, never over-confident.
  EXPECT_LT(theory.actual_error(0, 0), theory.posterior(0, 0));

  // The raw measurements' mean error is sqrt(8/pi) sigma, within 6 % over 750 independent frames
  // (4 sigma of 0.42 / sqrt(750)). Theory says the filter's is sqrt(E_xx) / sigma = 0.41 times
  // that; with both bands the measured ratio is at most 1.14 / 0.94 times the theoretical one.
  EXPECT_NEAR(raw_mean, kMeanNormFactor * sigma, 0.06 * kMeanNormFactor * sigma);
  const double theoretical_ratio = std::sqrt(theory.actual_error(0, 0)) / sigma;
  EXPECT_LT(theoretical_ratio, 0.45);
  EXPECT_LT(filter_mean / raw_mean, 1.14 / 0.94 * theoretical_ratio);
}

TEST(ConstantVelocityKalman, ErrorMatchesReportedCovarianceWhenTruthFollowsTheModel) {
  // The truth is drawn from the filter's own model (white-noise acceleration, exactly discretised)
  // with the default options, so the reported covariance is the true error covariance and the
  // mean error must match sqrt(8/pi) sqrt(P_xx) read from the estimates themselves.
  const CvKalmanOptions options;
  const double sigma = options.observation_noise_translation;
  const Matrix6 f = model_transition(Eigen::Matrix3d::Identity());
  const Matrix6 q = model_process_noise(options.acceleration_noise);
  constexpr int kFrames = 900;
  constexpr int kBurnIn = 90;
  ASSERT_TRUE(settled(steady_state(f, q, sigma * sigma), kBurnIn));

  const Matrix6 cholesky = q.llt().matrixL();
  ConstantVelocityKalman filter(options);
  Random rng(23);
  Eigen::Matrix<double, 6, 1> state;
  state << kLineStart, kLineVelocity;
  double error_sum = 0.0, expected_sum = 0.0;
  for (int k = 0; k < kFrames; ++k) {
    if (k > 0) {
      Eigen::Matrix<double, 6, 1> w;
      for (int i = 0; i < 6; ++i) w[i] = rng.normal();
      state = f * state + cholesky * w;
    }
    const mrpt::poses::CPose3D truth = make_pose(state.head<3>(), kLineOrientation);
    const mrpt::poses::CPose3D z = noisy(state.head<3>(), kLineOrientation, options, rng);
    const Estimate e =
        k == 0 ? filter.initialise(k * kDt, z) : filter.step(k * kDt, &z, kNoEnsemble);
    if (k < kBurnIn) continue;
    error_sum += translation_error(e.pose.mean, truth);
    expected_sum += kMeanNormFactor * std::sqrt(position_variance(e));
  }
  // One frame's error norm has a relative std of 0.42; the errors are correlated over fewer
  // frames here (closed-loop radius 0.68): ~370 effective samples of 810, 1 sigma 2.2 % (1000
  // seeds: 1.000 +- 0.022). The band is 4 sigma.
  EXPECT_GT(error_sum, 0.91 * expected_sum);
  EXPECT_LT(error_sum, 1.09 * expected_sum);
}

TEST(ConstantVelocityKalman, PredictsThroughAGapAlongTheLine) {
  const Theory theory = line_theory();
  // Converged by 6 s; then 1 s (30 frames) without measurements, then 3 s with.
  constexpr int kGapBegin = 180;
  constexpr int kGapFrames = 30;
  constexpr int kGapEnd = kGapBegin + kGapFrames;
  constexpr int kAfter = 90;
  constexpr int kFrames = kGapEnd + kAfter;
  ASSERT_TRUE(settled(theory, kGapBegin));
  const GapTheory gap = through_gap(theory, kGapFrames, kAfter);

  const Track track = run_line(5, kFrames, kGapBegin, kGapEnd);
  for (int k = 0; k < kFrames; ++k) {
    const bool in_gap = k >= kGapBegin && k < kGapEnd;
    EXPECT_EQ(track.estimates[k].mode, in_gap ? EstimateMode::kPredicted : EstimateMode::kMeasured)
        << "frame " << k;
  }
  const Estimate& before = track.estimates[kGapBegin - 1];
  const Estimate& last = track.estimates[kGapEnd - 1];
  ASSERT_LT(relative_difference(position_variance(before), theory.posterior(0, 0)), 1e-9);

  // The reported variance is the pure prediction F P F^T + Q, exactly, and grows at every frame.
  double previous_variance = position_variance(before);
  for (int k = kGapBegin; k < kFrames; ++k) {
    const double variance = position_variance(track.estimates[k]);
    EXPECT_LT(relative_difference(variance, gap.filter[k - kGapBegin](0, 0)), 1e-9)
        << "frame " << k;
    if (k < kGapEnd) {
      EXPECT_GT(variance, previous_variance) << "frame " << k;
    }
    previous_variance = variance;
  }

  // The true error at the gap's end is F^30 e, e ~ N(0, E): 99.9 % below 4.034 times its per-axis
  // std. That is a few cm, where standing still would miss by |v| * 1 s = 0.54 m. It lies well
  // inside the filter's own (wider, as Q expects accelerations) 3-sigma per axis too.
  const double true_std = std::sqrt(gap.error[kGapFrames - 1](0, 0));
  const double end_error = translation_error(last.pose.mean, track.truth[kGapEnd - 1]);
  EXPECT_LT(end_error, kNormQuantile999 * true_std);
  EXPECT_LT(kNormQuantile999 * true_std, 0.15 * kLineVelocity.norm());
  EXPECT_LT(end_error, 3.0 * std::sqrt(position_variance(last)));
  // So it moved by |v| * 1 s along the line during the gap.
  const Eigen::Vector3d moved = translation_of(last.pose.mean) - translation_of(before.pose.mean);
  EXPECT_NEAR(moved.dot(kLineVelocity.normalized()), kLineVelocity.norm() * kGapFrames * kDt,
              kNormQuantile999 * (true_std + std::sqrt(theory.actual_error(0, 0))));

  // Once measured again it converges back: the last frame's error against its 99.9 % bound from
  // the exact error covariance after 90 updates.
  const double after_error =
      translation_error(track.estimates.back().pose.mean, track.truth.back());
  EXPECT_LT(after_error, kNormQuantile999 * std::sqrt(gap.error.back()(0, 0)));
}

TEST(ConstantVelocityKalman, TracksAConstantRateRotationAndExtrapolatesIt) {
  const Theory theory = rotation_theory();
  const double sigma = tracking_options().observation_noise_rotation;
  constexpr int kBurnIn = 210;     // 7 s
  constexpr int kGapBegin = 1200;  // 40 s
  constexpr int kGapFrames = 30;
  constexpr int kGapEnd = kGapBegin + kGapFrames;
  constexpr int kAfter = 210;
  constexpr int kFrames = kGapEnd + kAfter;  // 48 s
  ASSERT_TRUE(settled(theory, kBurnIn));
  const GapTheory gap = through_gap(theory, kGapFrames, kAfter);

  const Track track = run_rotation(7, kFrames, kGapBegin, kGapEnd);

  // RMS geodesic error before the gap against sqrt(trace E) (E||e||^2 = trace E for any Gaussian).
  // One frame's ||e||^2 has a relative std of about 0.82 and the errors are correlated over tens
  // of frames (closed-loop radius 0.925): ~120 effective samples of 990 put 1 sigma of the RMS at
  // 3.7 % (1000 seeds over 270 frames gave 7 %, i.e. 3.7 % over 990). The band is 4 sigma.
  double squared_sum = 0.0;
  for (int k = kBurnIn; k < kGapBegin; ++k) {
    const double e = rotation_error_geodesic(track.estimates[k].pose.mean, track.truth[k]);
    squared_sum += e * e;
  }
  const double rms = std::sqrt(squared_sum / (kGapBegin - kBurnIn));
  const double expected_rms = std::sqrt(theory.actual_error.topLeftCorner<3, 3>().trace());
  EXPECT_GT(rms, 0.85 * expected_rms);
  EXPECT_LT(rms, 1.15 * expected_rms);
  EXPECT_LT(expected_rms, 0.4 * std::sqrt(3.0) * sigma);  // the raw measurements' RMS error

  // Through the 1 s gap the true error is F^30 e, e ~ N(0, E): its norm stays below 4.034 times
  // the square root of the largest eigenvalue with 99.9 % probability. That is about 0.2 rad,
  // where holding the orientation still would be off by |w| * 1 s = 1.2 rad.
  for (int k = kGapBegin; k < kGapEnd; ++k)
    EXPECT_EQ(track.estimates[k].mode, EstimateMode::kPredicted) << "frame " << k;
  EXPECT_EQ(track.estimates[kGapEnd].mode, EstimateMode::kMeasured);
  const double bound =
      kNormQuantile999 *
      std::sqrt(largest_eigenvalue(gap.error[kGapFrames - 1].topLeftCorner<3, 3>()));
  const double end_error =
      rotation_error_geodesic(track.estimates[kGapEnd - 1].pose.mean, track.truth[kGapEnd - 1]);
  EXPECT_LT(end_error, bound);
  EXPECT_LT(bound, 0.2 * kRate.norm() * kGapFrames * kDt);

  // Back to the steady level after the gap: the last frame against its 99.9 % bound.
  const double after_bound =
      kNormQuantile999 * std::sqrt(largest_eigenvalue(gap.error.back().topLeftCorner<3, 3>()));
  EXPECT_LT(rotation_error_geodesic(track.estimates.back().pose.mean, track.truth.back()),
            after_bound);
}

TEST(ConstantVelocityKalman, QuaternionSignOfTheMeasurementDoesNotMatter) {
  // The same orientations given as q to one filter and as -q on every other frame to another.
  // (A CPose3D keeps a rotation matrix, so the sign is gone before the filter sees it; this pins
  // that down at the interface.)
  const CvKalmanOptions options = tracking_options();
  ConstantVelocityKalman plus(options), mixed(options);
  Random rng(3);
  for (int k = 0; k < 120; ++k) {
    const double t = k * kDt;
    const Eigen::Quaterniond q = kStartOrientation * so3::exp(t * kRate + 0.05 * normal3(rng));
    const Eigen::Vector3d p = kPosition + 0.01 * normal3(rng);
    const double s = k % 2 == 0 ? -1.0 : 1.0;
    const mrpt::poses::CPose3D z_plus(mrpt::math::CQuaternionDouble(q.w(), q.x(), q.y(), q.z()),
                                      p.x(), p.y(), p.z());
    const mrpt::poses::CPose3D z_mixed(
        mrpt::math::CQuaternionDouble(s * q.w(), s * q.x(), s * q.y(), s * q.z()), p.x(), p.y(),
        p.z());
    const Estimate a = k == 0 ? plus.initialise(t, z_plus) : plus.step(t, &z_plus, kNoEnsemble);
    const Estimate b = k == 0 ? mixed.initialise(t, z_mixed) : mixed.step(t, &z_mixed, kNoEnsemble);
    EXPECT_LT(rotation_error_geodesic(a.pose.mean, b.pose.mean), 1e-12) << "frame " << k;
    EXPECT_LT(translation_error(a.pose.mean, b.pose.mean), 1e-12) << "frame " << k;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) EXPECT_NEAR(a.pose.cov(r, c), b.pose.cov(r, c), 1e-12);
  }

  // Inside the filter, the measured quaternions (converted from rotation matrices) land on either
  // hemisphere relative to the filter's continuously propagated one, which stays next to the
  // truth's. Over four turns both cases occur many times, and no frame's error jumps: all stay
  // below 1.5 times the steady 99.9 % bound (the largest of 510 frames may exceed the bound
  // itself by chance, not by 50 %).
  const Theory theory = rotation_theory();
  constexpr int kFrames = 720;
  constexpr int kBurnIn = 210;
  const Track track = run_rotation(13, kFrames, kFrames, kFrames);
  EXPECT_GT(track.flipped_measurements, 100);
  EXPECT_LT(track.flipped_measurements, kFrames - 100);
  const double bound = 1.5 * kNormQuantile999 *
                       std::sqrt(largest_eigenvalue(theory.actual_error.topLeftCorner<3, 3>()));
  for (int k = kBurnIn; k < kFrames; ++k)
    EXPECT_LT(rotation_error_geodesic(track.estimates[k].pose.mean, track.truth[k]), bound)
        << "frame " << k;
}

TEST(ConstantVelocityKalman, NonIncreasingTimeThrowsAndLeavesTheFilterUnchanged) {
  const CvKalmanOptions options;
  const mrpt::poses::CPose3D z0 = make_pose(kPosition, kStartOrientation);
  const mrpt::poses::CPose3D z1 =
      make_pose(kPosition + Eigen::Vector3d(0.01, 0.0, 0.0),
                kStartOrientation * so3::exp(Eigen::Vector3d(0.0, 0.0, 0.02)));

  ConstantVelocityKalman filter(options);
  EXPECT_THROW(filter.step(1.0, &z1, kNoEnsemble), std::logic_error);  // not initialised
  filter.initialise(1.0, z0);
  EXPECT_THROW(filter.step(1.0, &z1, kNoEnsemble), std::invalid_argument);
  EXPECT_THROW(filter.step(0.5, &z1, kNoEnsemble), std::invalid_argument);
  EXPECT_THROW(filter.step(0.5, nullptr, kNoEnsemble), std::invalid_argument);
  EXPECT_THROW(filter.step(std::numeric_limits<double>::quiet_NaN(), &z1, kNoEnsemble),
               std::invalid_argument);

  // The rejected calls changed nothing: the next valid step matches an untouched filter's.
  ConstantVelocityKalman fresh(options);
  fresh.initialise(1.0, z0);
  const Estimate a = filter.step(1.1, &z1, kNoEnsemble);
  const Estimate b = fresh.step(1.1, &z1, kNoEnsemble);
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.pose.mean, b.pose.mean);
  EXPECT_EQ(a.pose.cov, b.pose.cov);
  EXPECT_THROW(filter.step(1.1, nullptr, kNoEnsemble), std::invalid_argument);
}

TEST(ConstantVelocityKalman, InvalidOptionsThrowNamingTheField) {
  struct Field {
    double CvKalmanOptions::*member;
    const char* name;
  };
  const Field fields[] = {
      {&CvKalmanOptions::acceleration_noise, "acceleration_noise"},
      {&CvKalmanOptions::angular_acceleration_noise, "angular_acceleration_noise"},
      {&CvKalmanOptions::observation_noise_translation, "observation_noise.translation"},
      {&CvKalmanOptions::observation_noise_rotation, "observation_noise.rotation"},
      {&CvKalmanOptions::initial_velocity_std, "initial_velocity_std"},
      {&CvKalmanOptions::initial_angular_velocity_std, "initial_angular_velocity_std"},
  };
  const double bad_values[] = {0.0, -0.1, std::numeric_limits<double>::quiet_NaN(),
                               std::numeric_limits<double>::infinity()};
  EXPECT_NO_THROW(ConstantVelocityKalman{CvKalmanOptions{}});
  for (const Field& field : fields) {
    for (const double value : bad_values) {
      CvKalmanOptions options;
      options.*field.member = value;
      try {
        ConstantVelocityKalman filter(options);
        ADD_FAILURE() << field.name << " = " << value << " was accepted";
      } catch (const std::invalid_argument& error) {
        // "option " + name: "acceleration_noise" alone is also inside the angular one.
        EXPECT_NE(std::string(error.what()).find(std::string("option ") + field.name),
                  std::string::npos)
            << error.what();
      }
    }
  }
}

}  // namespace
}  // namespace opf
