#include "opf/fit/trajectory_fit.h"

#include "opf/core/random.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace opf {
namespace {

// A start time far from zero, so that the fit's use of t_ref = last sample's time is exercised.
constexpr double kStart = 12.0;
constexpr double kRate = 100.0;  // Hz
constexpr int kCount = 50;       // the paper's H
// Quantiles of the norm of a standard normal vector for a tail probability of 1e-4, from the
// chi-square quantiles 18.42 (2 dof) and 21.11 (3 dof): "4 sigma" for a 2-D or 3-D error.
constexpr double kChi2Dof = 4.29;
constexpr double kChi3Dof = 4.6;

using Vector6d = Eigen::Matrix<double, 6, 1>;

std::vector<double> even_times(int count = kCount) {
  std::vector<double> times;
  for (int k = 0; k < count; ++k) times.push_back(kStart + k / kRate);
  return times;
}

std::vector<TrajectorySample> sample(const std::vector<double>& times,
                                     const std::function<Eigen::Vector3d(double)>& position,
                                     const std::function<Eigen::Quaterniond(double)>& orientation) {
  std::vector<TrajectorySample> samples;
  for (double t : times) samples.push_back({t, position(t), orientation(t)});
  return samples;
}

// Isotropic Gaussian noise: sigma_p per axis on positions, sigma_r per body axis on orientations
// (q * exp(sigma_r n), the right-perturbation convention of so3.h).
void add_noise(std::vector<TrajectorySample>& samples, double sigma_p, double sigma_r,
               Random& random) {
  for (TrajectorySample& s : samples) {
    const Eigen::Vector3d dp(random.normal(), random.normal(), random.normal());
    const Eigen::Vector3d dr(random.normal(), random.normal(), random.normal());
    s.position += sigma_p * dp;
    s.orientation = s.orientation * so3::exp(sigma_r * dr);
  }
}

Eigen::VectorXd monomials(double dt, int order) {
  Eigen::VectorXd phi(order + 1);
  for (int k = 0; k <= order; ++k) phi(k) = std::pow(dt, k);
  return phi;
}

// Rows of monomials of (t - t_ref): the design matrix of the least-squares polynomial fit.
Eigen::MatrixXd design(const std::vector<double>& times, double t_ref, int order) {
  Eigen::MatrixXd v(static_cast<Eigen::Index>(times.size()), order + 1);
  for (std::size_t k = 0; k < times.size(); ++k) {
    v.row(static_cast<Eigen::Index>(k)) = monomials(times[k] - t_ref, order).transpose();
  }
  return v;
}

// Standard deviation, per axis, of the least-squares polynomial's value at t for unit noise:
// sqrt(phi(t)^T (V^T V)^-1 phi(t)), the coefficients' covariance sigma^2 (V^T V)^-1 propagated.
double prediction_std(const std::vector<double>& times, double t, int order) {
  const Eigen::MatrixXd v = design(times, times.back(), order);
  const Eigen::VectorXd phi = monomials(t - times.back(), order);
  return std::sqrt(phi.dot((v.transpose() * v).ldlt().solve(phi)));
}

double axis_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

template <typename F>
Eigen::MatrixXd numeric_jacobian(const F& f, Eigen::Index rows) {
  constexpr double kStep = 1e-6;
  Eigen::MatrixXd jacobian(rows, 6);
  for (int j = 0; j < 6; ++j) {
    Vector6d plus = Vector6d::Zero(), minus = Vector6d::Zero();
    plus(j) = kStep;
    minus(j) = -kStep;
    jacobian.col(j) = (f(plus) - f(minus)) / (2.0 * kStep);
  }
  return jacobian;
}

// A constant rate about a fixed body axis, and the test's own, Ceres-free, copy of the rotation
// model about it: theta = (reference offset (3), axis tilt (2), rate change (1)). The fit is
// least squares in these residuals, so to first order in the noise its parameter error is
// -(J^T J)^-1 J^T r with covariance sigma^2 (J^T J)^-1 (the Huber loss is quadratic at this noise:
// the 3-D residual norm stays below rotation_loss_scale = 5 sigma but with probability ~1e-5).
struct Spin {
  Eigen::Quaterniond r0;  // truth at t_ref
  Eigen::Vector3d axis;
  double rate;
  double t_ref;

  Eigen::Quaterniond at(double t) const { return r0 * so3::exp(rate * (t - t_ref) * axis); }

  Eigen::Quaterniond model(const Vector6d& theta, double t) const {
    const Eigen::Vector3d b1 = axis.unitOrthogonal();
    const Eigen::Vector3d b2 = axis.cross(b1);
    const Eigen::Vector3d e = (axis + theta(3) * b1 + theta(4) * b2).normalized();
    return r0 * so3::exp(theta.head<3>()) * so3::exp((rate + theta(5)) * (t - t_ref) * e);
  }

  // d/dtheta of every sample's residual log(model^-1 truth), 3 rows per sample.
  Eigen::MatrixXd residual_jacobian(const std::vector<double>& times) const {
    const auto residuals = [&](const Vector6d& theta) {
      Eigen::VectorXd r(3 * static_cast<Eigen::Index>(times.size()));
      for (std::size_t k = 0; k < times.size(); ++k) {
        r.segment<3>(3 * static_cast<Eigen::Index>(k)) =
            so3::difference(model(theta, times[k]), at(times[k]));
      }
      return r;
    };
    return numeric_jacobian(residuals, 3 * std::ssize(times));
  }

  // d/dtheta of the model's orientation error at t, log(truth^-1 model).
  Eigen::MatrixXd error_jacobian(double t) const {
    const auto error = [&](const Vector6d& theta) {
      return Eigen::VectorXd(so3::difference(at(t), model(theta, t)));
    };
    return numeric_jacobian(error, 3);
  }
};

double largest_eigenvalue(const Eigen::MatrixXd& covariance) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(covariance).eigenvalues().maxCoeff();
}

const Eigen::Vector3d kP0(0.4, -0.1, 0.02);
const Eigen::Vector3d kV0(0.3, -0.2, 0.05);
const Eigen::Quaterniond kR0 = so3::exp(Eigen::Vector3d(0.2, 0.4, -1.1));
const Eigen::Vector3d kTiltedAxis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();

Eigen::Vector3d linear(double t) {
  return kP0 + kV0 * (t - kStart);
}
Eigen::Quaterniond fixed_orientation(double) {
  return kR0;
}

// A throw: v0 = (1, 0.5, 3) m/s, gravity -9.81 m/s^2 along z.
Eigen::Vector3d ballistic(double t) {
  const double s = t - kStart;
  return kP0 + Eigen::Vector3d(1.0, 0.5, 3.0) * s + Eigen::Vector3d(0.0, 0.0, -0.5 * 9.81) * s * s;
}

TEST(TrajectoryFit, ExactLinearMotionIsReproducedAndExtrapolated) {
  const auto times = even_times();
  const auto samples = sample(times, linear, fixed_orientation);
  const TrajectoryModel model = fit_trajectory(samples, {});

  EXPECT_EQ(model.reference_time(), times.back());
  for (double t : times) EXPECT_LT((model.position(t) - linear(t)).norm(), 1e-9) << t;
  const double ahead = times.back() + 1.0;
  EXPECT_LT((model.position(ahead) - linear(ahead)).norm(), 1e-9);
  EXPECT_LT((model.velocity(ahead) - kV0).norm(), 1e-9);
  EXPECT_LT((model.translation_coefficient(1) - kV0).norm(), 1e-9);
  EXPECT_LT(so3::angle_between(model.orientation(ahead), kR0), 1e-9);
  EXPECT_LT(model.angular_rate(ahead), 1e-9);
}

TEST(TrajectoryFit, BallisticMotionNeedsOrderTwo) {
  const auto times = even_times();
  const double ahead = times.back() + 0.5;
  TrajectoryFitOptions order2;
  order2.translation_order = 2;

  // Exact data: a parabola is in the model, so only rounding remains (the brief's 1 mm is loose).
  const auto exact = sample(times, ballistic, fixed_orientation);
  EXPECT_LT((fit_trajectory(exact, order2).position(ahead) - ballistic(ahead)).norm(), 1e-8);

  constexpr double kSigma = 0.002;
  auto noisy = exact;
  Random random(21);
  add_noise(noisy, kSigma, 0.0, random);
  const TrajectoryModel fit2 = fit_trajectory(noisy, order2);
  const Eigen::Vector3d error2 = fit2.position(ahead) - ballistic(ahead);
  // 4 sigma per axis of the least-squares extrapolation (0.5 s beyond a 0.49 s window: sigma is
  // 4.1 times the noise, 8.3 mm).
  const double sigma2 = kSigma * prediction_std(times, ahead, 2);
  for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(error2(i)), 4.0 * sigma2) << "axis " << i;

  // A line through a parabola: the bias at `ahead` is the least-squares line fit's error on the
  // exact data, |g|/2 * 0.535 s^2 ~ 2.6 m along z; the line's own noise sigma is 1.5 mm.
  TrajectoryFitOptions squared1;
  squared1.loss = RobustLoss::kSquared;
  const TrajectoryModel fit1 = fit_trajectory(noisy, squared1);
  const Eigen::MatrixXd v1 = design(times, times.back(), 1);
  Eigen::VectorXd z(kCount);
  for (int k = 0; k < kCount; ++k) z(k) = ballistic(times[k]).z();
  const Eigen::VectorXd line = (v1.transpose() * v1).ldlt().solve(v1.transpose() * z);
  const double bias = ballistic(ahead).z() - line.dot(monomials(ahead - times.back(), 1));
  const double sigma1 = kSigma * prediction_std(times, ahead, 1);
  const double error1 = fit1.position(ahead).z() - ballistic(ahead).z();
  EXPECT_NEAR(error1, -bias, 4.0 * sigma1);
  EXPECT_GT(std::abs(error1), 50.0 * 4.0 * sigma2);
  // The default (Huber) line is as far off: the parabola's own residuals exceed the loss scale.
  EXPECT_GT((fit_trajectory(noisy, {}).position(ahead) - ballistic(ahead)).norm(),
            50.0 * 4.0 * sigma2);
}

TEST(TrajectoryFit, SquaredLossEqualsClosedFormLeastSquares) {
  const auto times = even_times();
  auto samples = sample(times, ballistic, fixed_orientation);
  Random random(5);
  add_noise(samples, 0.005, 0.0, random);
  Eigen::MatrixXd p(kCount, 3);
  for (int k = 0; k < kCount; ++k) p.row(k) = samples[k].position.transpose();

  for (int order = 0; order <= 3; ++order) {
    TrajectoryFitOptions options;
    options.loss = RobustLoss::kSquared;
    options.translation_order = order;
    const TrajectoryModel model = fit_trajectory(samples, options);
    const Eigen::MatrixXd v = design(times, times.back(), order);
    const Eigen::MatrixXd c = (v.transpose() * v).ldlt().solve(v.transpose() * p);  // (order+1)x3
    for (int k = 0; k <= order; ++k) {
      EXPECT_LT((model.translation_coefficient(k) - c.row(k).transpose()).norm(), 1e-8)
          << "order " << order << " coefficient " << k;
    }
    EXPECT_TRUE(model.translation_summary().converged) << order;
  }
}

TEST(TrajectoryFit, RobustLossesRejectGrossOutliers) {
  constexpr double kSigma = 0.002;
  constexpr double kOutlier = 0.3;
  const std::vector<int> outliers = {20, 35, 47};
  const auto times = even_times();
  auto samples = sample(times, linear, fixed_orientation);
  Random random(8);
  add_noise(samples, kSigma, 0.0, random);
  for (int k : outliers) samples[k].position.x() += kOutlier;
  const double ahead = times.back() + 0.5;

  TrajectoryFitOptions squared;
  squared.loss = RobustLoss::kSquared;
  const double squared_error =
      (fit_trajectory(samples, squared).position(ahead) - linear(ahead)).norm();

  // Bound: the inliers' least-squares extrapolation noise (chi, 3 dof) plus the outliers' pull.
  // Huber's influence is capped: an outlier acts like an inlier whose residual is the loss scale
  // a, so it moves the extrapolation by at most a |h(ahead, t_j)|, h the inliers' hat function
  // phi(ahead)^T (V^T V)^-1 phi(t_j). Cauchy's influence r / (1 + r^2 / a^2) is below a / 2.
  std::vector<double> inlier_times;
  for (int k = 0; k < kCount; ++k) {
    if (std::find(outliers.begin(), outliers.end(), k) == outliers.end()) {
      inlier_times.push_back(times[k]);
    }
  }
  const Eigen::MatrixXd v = design(inlier_times, times.back(), 1);
  const Eigen::VectorXd phi = monomials(ahead - times.back(), 1);
  const Eigen::VectorXd weights = (v.transpose() * v).ldlt().solve(phi);
  double pull = 0.0;
  for (int k : outliers) pull += std::abs(weights.dot(monomials(times[k] - times.back(), 1)));
  const TrajectoryFitOptions defaults;
  const double bound =
      kChi3Dof * kSigma * std::sqrt(phi.dot(weights)) + defaults.translation_loss_scale * pull;

  for (RobustLoss loss : {RobustLoss::kHuber, RobustLoss::kCauchy}) {
    TrajectoryFitOptions options;
    options.loss = loss;
    const double error = (fit_trajectory(samples, options).position(ahead) - linear(ahead)).norm();
    EXPECT_LT(error, squared_error / 3.0) << static_cast<int>(loss);
    EXPECT_LT(error, bound) << static_cast<int>(loss);
  }
}

TEST(TrajectoryFit, RotationExactDataIsReproduced) {
  const auto times = even_times();
  const Spin spin{kR0, kTiltedAxis, 0.8, times.back()};
  const auto samples = sample(times, linear, [&](double t) { return spin.at(t); });
  const TrajectoryModel model = fit_trajectory(samples, {});

  EXPECT_LT(axis_angle(model.axis(), kTiltedAxis), 1e-9);
  EXPECT_NEAR(model.angular_rate(times.back()), 0.8, 1e-9);
  EXPECT_NEAR(model.axis().norm(), 1.0, 1e-12);
  for (double t : times) EXPECT_LT(so3::angle_between(model.orientation(t), spin.at(t)), 1e-9);
  const double ahead = times.back() + 0.5;
  EXPECT_LT(so3::angle_between(model.orientation(ahead), spin.at(ahead)), 1e-9);
  EXPECT_LT(so3::angle_between(model.reference_orientation(), samples.back().orientation), 1e-9);
}

TEST(TrajectoryFit, RotationSignIsNormalisedToAPositiveRate) {
  const auto times = even_times();
  const double ahead = times.back() + 0.5;
  const Spin spin{kR0, kTiltedAxis, -0.8, times.back()};
  const TrajectoryModel backwards =
      fit_trajectory(sample(times, linear, [&](double t) { return spin.at(t); }), {});
  EXPECT_LT(axis_angle(backwards.axis(), -kTiltedAxis), 1e-9);
  EXPECT_NEAR(backwards.angular_rate(times.back()), 0.8, 1e-9);
  EXPECT_NEAR(backwards.rotation_coefficient(1), 0.8, 1e-9);
  EXPECT_LT(so3::angle_between(backwards.orientation(ahead), spin.at(ahead)), 1e-9);

  // omega(t) = -0.5 dt - 4 dt^2: the window's net turn is +0.72 rad about the axis, which is where
  // the fit starts, but the rate at t_ref is -0.5 rad/s, so the solution must be flipped.
  const auto reversing = [&](double t) {
    const double dt = t - times.back();
    return kR0 * so3::exp((-0.5 * dt - 4.0 * dt * dt) * kTiltedAxis);
  };
  TrajectoryFitOptions options;
  options.rotation_order = 2;
  const TrajectoryModel model = fit_trajectory(sample(times, linear, reversing), options);
  EXPECT_LT(axis_angle(model.axis(), -kTiltedAxis), 1e-9);
  EXPECT_NEAR(model.angular_rate(times.back()), 0.5, 1e-9);
  EXPECT_NEAR(model.rotation_coefficient(2), 4.0, 1e-9);
  EXPECT_LT(so3::angle_between(model.orientation(ahead), reversing(ahead)), 1e-9);
}

TEST(TrajectoryFit, RotationOfMoreThanHalfATurnOverTheWindowIsFitted) {
  // 8 rad/s over 0.49 s is 3.9 rad: log(R_first^-1 R_last) would wrap to the other way round.
  const auto times = even_times();
  const Spin spin{kR0, kTiltedAxis, 8.0, times.back()};
  const auto samples = sample(times, linear, [&](double t) { return spin.at(t); });
  const TrajectoryModel model = fit_trajectory(samples, {});

  EXPECT_NEAR(model.angular_rate(times.back()), 8.0, 1e-9);
  EXPECT_LT(axis_angle(model.axis(), kTiltedAxis), 1e-9);
  const double ahead = times.back() + 0.5;
  EXPECT_LT(so3::angle_between(model.orientation(ahead), spin.at(ahead)), 1e-9);
}

TEST(TrajectoryFit, RotationWithNoiseRecoversAxisRateAndExtrapolation) {
  constexpr double kSigma = 0.01;
  const auto times = even_times();
  const Spin spin{kR0, kTiltedAxis, 0.8, times.back()};
  auto samples = sample(times, linear, [&](double t) { return spin.at(t); });
  Random random(13);
  add_noise(samples, 0.0, kSigma, random);
  const TrajectoryModel model = fit_trajectory(samples, {});
  const double ahead = times.back() + 0.5;

  const Eigen::MatrixXd j = spin.residual_jacobian(times);
  const Eigen::MatrixXd covariance =
      kSigma * kSigma * (j.transpose() * j).inverse();  // of theta, 6x6
  // Rate: 1-D, 4 sigma (~0.04 rad/s: sigma / sqrt(sum (t - mean t)^2)).
  EXPECT_NEAR(model.angular_rate(times.back()), 0.8, 4.0 * std::sqrt(covariance(5, 5)));
  // Axis: the tilt is a 2-D error (~0.05 rad: the rate's sigma over the rate).
  const double axis_sigma = std::sqrt(largest_eigenvalue(covariance.block<2, 2>(3, 3)));
  EXPECT_LT(axis_angle(model.axis(), kTiltedAxis), kChi2Dof * axis_sigma);
  // Orientation 0.5 s ahead: a 3-D error (~0.035 rad).
  const Eigen::MatrixXd g = spin.error_jacobian(ahead);
  const double ahead_sigma = std::sqrt(largest_eigenvalue(g * covariance * g.transpose()));
  EXPECT_LT(so3::angle_between(model.orientation(ahead), spin.at(ahead)), kChi3Dof * ahead_sigma);
}

TEST(TrajectoryFit, NoiseOnTheLastSampleDoesNotPinTheOrientation) {
  // Exact data except the last sample, turned 0.02 rad across the axis. Were R_ref that sample,
  // the whole extrapolation would be 0.02 rad off; fitted, only its least-squares share remains.
  constexpr double kKick = 0.02;
  const auto times = even_times();
  const Spin spin{kR0, kTiltedAxis, 0.8, times.back()};
  auto samples = sample(times, linear, [&](double t) { return spin.at(t); });
  const Eigen::Vector3d kick = kKick * kTiltedAxis.unitOrthogonal();
  samples.back().orientation = samples.back().orientation * so3::exp(kick);
  TrajectoryFitOptions options;
  options.loss = RobustLoss::kSquared;
  const TrajectoryModel model = fit_trajectory(samples, options);

  // First order: theta = -(J^T J)^-1 J^T r with r the kick in the last residual (here
  // log(model^-1 sample) = +kick at theta = 0, and residual_jacobian's sign is that of r).
  const Eigen::MatrixXd j = spin.residual_jacobian(times);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(j.rows());
  r.tail<3>() = kick;
  const Vector6d theta = -(j.transpose() * j).ldlt().solve(j.transpose() * r);
  const Eigen::Vector3d predicted = spin.error_jacobian(times.back()) * theta;
  const double error = so3::angle_between(model.reference_orientation(), spin.at(times.back()));
  EXPECT_LT(error, 0.2 * kKick);
  // Second-order terms are O(kick^2) ~ 4e-4 of it: 1% slack.
  EXPECT_NEAR(error, predicted.norm(), 0.01 * predicted.norm() + 1e-7);
}

TEST(TrajectoryFit, StaticObjectGivesZeroRateAndFiniteValues) {
  const auto times = even_times();
  const auto still = sample(
      times, [](double) { return kP0; }, fixed_orientation);
  const double ahead = times.back() + 1.0;

  // Exact: no rotation to take an axis from, so the fit starts and stays at (0, 0, 1), rate 0.
  const TrajectoryModel exact = fit_trajectory(still, {});
  EXPECT_EQ(exact.angular_rate(times.back()), 0.0);
  EXPECT_EQ(exact.axis(), Eigen::Vector3d::UnitZ());
  EXPECT_LT(exact.velocity(ahead).norm(), 1e-12);
  EXPECT_LT(so3::angle_between(exact.orientation(ahead), kR0), 1e-12);
  EXPECT_LT((exact.position(ahead) - kP0).norm(), 1e-12);

  // Tiny noise. At order 1 the fitted slope vectors (rate * axis, and the velocity) are
  // least-squares slopes per component, N(0, sigma^2 / S_tt) with S_tt = sum (t - mean t)^2, so
  // their norms are chi with 3 dof times sigma / sqrt(S_tt) (~1e-5 rad/s here).
  constexpr double kSigma = 1e-5;
  double mean = 0.0, s_tt = 0.0;
  for (double t : times) mean += t / kCount;
  for (double t : times) s_tt += (t - mean) * (t - mean);
  const double bound = kChi3Dof * kSigma / std::sqrt(s_tt);
  for (RobustLoss loss : {RobustLoss::kSquared, RobustLoss::kHuber, RobustLoss::kCauchy}) {
    for (int order : {1, 2}) {
      auto noisy = still;
      Random random(3);
      add_noise(noisy, kSigma, kSigma, random);
      TrajectoryFitOptions options;
      options.loss = loss;
      options.translation_order = options.rotation_order = order;
      const TrajectoryModel model = fit_trajectory(noisy, options);
      SCOPED_TRACE(testing::Message() << "loss " << static_cast<int>(loss) << " order " << order);
      // Order 2 makes the axis nearly unobservable (the fit may stop at the iteration limit);
      // it must still return finite values and a unit axis.
      for (int k = 0; k <= order; ++k) {
        EXPECT_TRUE(model.translation_coefficient(k).allFinite());
        EXPECT_TRUE(std::isfinite(model.rotation_coefficient(k)));
      }
      EXPECT_NEAR(model.axis().norm(), 1.0, 1e-12);
      EXPECT_GE(model.angular_rate(times.back()), 0.0);
      EXPECT_TRUE(model.orientation(ahead).coeffs().allFinite());
      // The fitted reference averages many samples: its error's sigma is below one sample's.
      EXPECT_LT(so3::angle_between(model.reference_orientation(), kR0), kChi3Dof * kSigma);
      if (order == 1) {
        EXPECT_LT(model.angular_rate(times.back()), bound);
        EXPECT_LT(model.velocity(times.back()).norm(), bound);
      }
    }
  }
}

void expect_invalid(std::span<const TrajectorySample> samples, const TrajectoryFitOptions& options,
                    const std::string& mentions) {
  try {
    fit_trajectory(samples, options);
    ADD_FAILURE() << "no exception; expected one mentioning " << mentions;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(mentions), std::string::npos) << e.what();
  }
}

TEST(TrajectoryFit, InvalidInputsThrow) {
  const auto samples = sample(even_times(5), linear, fixed_orientation);
  const std::span<const TrajectorySample> all(samples);
  TrajectoryFitOptions options;

  expect_invalid({}, options, "at least 2 samples");
  expect_invalid(all.first(1), options, "at least 2 samples");
  options.translation_order = 5;
  expect_invalid(all, options, "at least 6 samples");
  options = {};
  options.rotation_order = 5;
  expect_invalid(all, options, "at least 6 samples");
  options.translation_order = 4;
  options.rotation_order = 4;
  EXPECT_NO_THROW(fit_trajectory(all, options));  // 5 samples suffice for order 4

  for (int order : {-1, kMaxTrajectoryOrder + 1}) {
    options = {};
    options.translation_order = order;
    expect_invalid(all, options, "translation_order");
    options = {};
    options.rotation_order = order;
    expect_invalid(all, options, "rotation_order");
  }
  for (double scale : {0.0, -0.01, std::nan("")}) {
    options = {};
    options.translation_loss_scale = scale;
    expect_invalid(all, options, "translation_loss_scale");
    options = {};
    options.rotation_loss_scale = scale;
    expect_invalid(all, options, "rotation_loss_scale");
  }
  options = {};
  options.max_iterations = 0;
  expect_invalid(all, options, "max_iterations");

  options = {};
  auto repeated = samples;
  repeated[3].t = repeated[2].t;
  expect_invalid(repeated, options, "strictly increasing");
  auto backwards = samples;
  backwards[3].t = backwards[1].t;
  expect_invalid(backwards, options, "strictly increasing");
  auto nan = samples;
  nan[2].position.y() = std::nan("");
  expect_invalid(nan, options, "non-finite");
  auto zero = samples;
  zero[2].orientation.coeffs().setZero();
  expect_invalid(zero, options, "zero orientation");
}

TEST(TrajectoryFit, UnevenTimestampsWorkOnExactData) {
  // Gaps of 4 to 34 ms, as from a detector that drops frames.
  Random random(17);
  std::vector<double> times = {kStart};
  while (times.size() < kCount) times.push_back(times.back() + 0.004 + 0.03 * random.uniform());
  const Spin spin{kR0, kTiltedAxis, 0.8, times.back()};
  const auto samples = sample(times, ballistic, [&](double t) { return spin.at(t); });
  TrajectoryFitOptions options;
  options.translation_order = 2;
  const TrajectoryModel model = fit_trajectory(samples, options);

  for (double t : times) {
    EXPECT_LT((model.position(t) - ballistic(t)).norm(), 1e-9);
    EXPECT_LT(so3::angle_between(model.orientation(t), spin.at(t)), 1e-9);
  }
  const double ahead = times.back() + 0.5;
  EXPECT_LT((model.position(ahead) - ballistic(ahead)).norm(), 1e-9);
  EXPECT_LT(so3::angle_between(model.orientation(ahead), spin.at(ahead)), 1e-9);
  EXPECT_NEAR(model.angular_rate(ahead), 0.8, 1e-9);
}

}  // namespace
}  // namespace opf
