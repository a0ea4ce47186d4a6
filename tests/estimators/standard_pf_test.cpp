#include "opf/estimators/standard_pf.h"

#include "opf/core/metrics.h"
#include "opf/core/pose_conversion.h"
#include "opf/core/random.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opf {
namespace {

constexpr double kDt = 1.0 / 30.0;
// E||e|| of a 3-D isotropic Gaussian with per-axis std s is s * 2 sqrt(2/pi).
const double kChi3Mean = 2.0 * std::sqrt(2.0 / std::numbers::pi);

// Steady-state per-axis error variance of a random-walk Kalman filter (process variance q per
// step, measurement variance r) tracking a STATIC truth: the filter is an exponential smoother
// with gain K, so e' = (1 - K) e + K n and Var(e) = K r / (2 - K).
double static_truth_error_variance(double q, double r) {
  const double p = 0.5 * (-q + std::sqrt(q * q + 4.0 * q * r));  // posterior variance
  const double gain = (p + q) / (p + q + r);
  return gain * r / (2.0 - gain);
}

const EnsembleView& no_ensemble() {
  static const Frame frame;
  static const EnsembleView view{frame, {}};
  return view;
}

// The PF approximates the Kalman filter of the same linear-Gaussian model, so its mean errors on a
// static object observed with noise sigma match the derived steady-state values. The window is
// 400 frames (correlation ~1/K frames), giving ~4% relative sampling spread: +-15% bounds.
TEST(StandardParticleFilter, ConvergesToTheKalmanSteadyStateOnAStaticObject) {
  PoseParticleFilterOptions options;
  options.observation_noise_translation = 0.01;
  options.observation_noise_rotation = 0.05;
  const Eigen::Vector3d truth_p(0.4, -0.1, 0.03);
  const Eigen::Quaterniond truth_q = so3::exp(Eigen::Vector3d(0.2, -0.3, 1.0));
  const mrpt::poses::CPose3D truth = make_pose(truth_p, truth_q);

  StandardParticleFilter pf(options, 11);
  Random noise(12);
  auto measure = [&] {
    const Eigen::Vector3d p =
        truth_p + 0.01 * Eigen::Vector3d(noise.normal(), noise.normal(), noise.normal());
    const Eigen::Quaterniond q =
        truth_q * so3::exp(0.05 * Eigen::Vector3d(noise.normal(), noise.normal(), noise.normal()));
    return make_pose(p, q);
  };
  pf.initialise(0.0, measure());
  double translation = 0.0, rotation = 0.0;
  constexpr int kBurnIn = 30, kFrames = 400;
  for (int k = 1; k <= kBurnIn + kFrames; ++k) {
    const auto z = measure();
    const Estimate e = pf.step(k * kDt, &z, no_ensemble());
    ASSERT_EQ(e.mode, EstimateMode::kMeasured);
    if (k > kBurnIn) {
      translation += translation_error(e.pose.mean, truth);
      rotation += rotation_error_geodesic(e.pose.mean, truth);
    }
  }
  translation /= kFrames;
  rotation /= kFrames;

  const double expected_t =
      kChi3Mean * std::sqrt(static_truth_error_variance(0.05 * 0.05 * kDt, 0.01 * 0.01));
  const double expected_r =
      kChi3Mean * std::sqrt(static_truth_error_variance(0.1 * 0.1 * kDt, 0.05 * 0.05));
  EXPECT_NEAR(translation, expected_t, 0.15 * expected_t);
  EXPECT_NEAR(rotation, expected_r, 0.15 * expected_r);
  // And clearly better than the raw measurements (E||n|| = sigma * kChi3Mean).
  EXPECT_LT(translation, 0.8 * 0.01 * kChi3Mean);
}

// Without a measurement the standard PF predicts only: the mean stays where the object vanished
// and every axis' variance grows by the random-walk density^2 * elapsed time.
TEST(StandardParticleFilter, PredictsOnlyWhenTheMeasurementIsMissing) {
  PoseParticleFilterOptions options;
  StandardParticleFilter pf(options, 21);
  const mrpt::poses::CPose3D z = make_pose({0.5, 0.0, 0.1}, Eigen::Quaterniond::Identity());
  pf.initialise(0.0, z);
  for (int k = 1; k <= 30; ++k) pf.step(k * kDt, &z, no_ensemble());
  const double before = pf.step(31 * kDt, &z, no_ensemble()).pose.cov(0, 0);

  Estimate e;
  constexpr int kGap = 30;  // one second
  for (int k = 32; k < 32 + kGap; ++k) {
    e = pf.step(k * kDt, nullptr, no_ensemble());
    EXPECT_EQ(e.mode, EstimateMode::kPredicted);
  }
  const double elapsed = kGap * kDt;
  const double grown =
      options.process_noise_translation * options.process_noise_translation * elapsed;
  // The sample variance of 5000 particles has relative error sqrt(2/5000) = 2%: allow 8%.
  EXPECT_NEAR(e.pose.cov(0, 0), before + grown, 0.08 * (before + grown));
  // The mean drifts only by the Monte Carlo error of the cloud's mean: sqrt(var / N) per axis.
  EXPECT_LT(translation_error(e.pose.mean, z), 5.0 * std::sqrt(3.0 * (before + grown) / 5000.0));
  EXPECT_DOUBLE_EQ(e.observation_trace, pf.filter().observation_trace());
}

// An object moved 0.3 m while unseen: no particle is within 5 sigma of its measurement, so the
// cloud is re-scattered around it (sensor resetting) and the first estimate after it reappears
// is already at the measurement, within a few observation sigmas of a single noisy sample. With
// resetting off the cloud crawls there by random walk (0.05 m/sqrt(s)) and is still far off.
TEST(StandardParticleFilter, SensorResettingReacquiresAMovedObjectAtOnce) {
  const auto run = [](double gate) {
    PoseParticleFilterOptions options;
    options.reset_gate = gate;
    StandardParticleFilter pf(options, 5);
    const auto here = make_pose({0.4, 0.0, 0.0}, Eigen::Quaterniond::Identity());
    const auto there = make_pose({0.4, 0.3, 0.0}, Eigen::Quaterniond::Identity());
    pf.initialise(0.0, here);
    for (int k = 1; k <= 30; ++k) pf.step(k * kDt, &here, no_ensemble());
    for (int k = 31; k <= 60; ++k) pf.step(k * kDt, nullptr, no_ensemble());
    return translation_error(pf.step(61 * kDt, &there, no_ensemble()).pose.mean, there);
  };
  // Scattered with sigma = 1 cm around the exact measurement: the mean of 5000 particles is
  // within 5 sigma / sqrt(5000) of it per axis.
  EXPECT_LT(run(5.0), 5.0 * std::sqrt(3.0) * 0.01 / std::sqrt(5000.0));
  EXPECT_GT(run(0.0), 0.1);
}

TEST(StandardParticleFilter, SameSeedIsBitIdenticalDifferentSeedIsNot) {
  PoseParticleFilterOptions options;
  options.translation_particles = options.rotation_particles = 500;
  auto run = [&](std::uint64_t seed) {
    StandardParticleFilter pf(options, seed);
    const auto z = make_pose({0.1, 0.2, 0.3}, so3::exp(Eigen::Vector3d(0.1, 0.2, 0.3)));
    pf.initialise(0.0, z);
    Estimate e;
    for (int k = 1; k < 20; ++k) e = pf.step(k * kDt, k % 3 ? &z : nullptr, no_ensemble());
    return e.pose.mean.asVectorVal();
  };
  EXPECT_EQ(run(3), run(3));
  EXPECT_NE(run(3), run(4));
}

TEST(StandardParticleFilter, RejectsTimeThatDoesNotAdvance) {
  StandardParticleFilter pf(PoseParticleFilterOptions{}, 1);
  const mrpt::poses::CPose3D z;
  pf.initialise(1.0, z);
  EXPECT_THROW(pf.step(1.0, &z, no_ensemble()), std::invalid_argument);
  EXPECT_THROW(pf.step(0.5, &z, no_ensemble()), std::invalid_argument);
}

TEST(StandardParticleFilter, RejectsBadOptionsNamingThem) {
  PoseParticleFilterOptions options;
  options.process_noise_rotation = -1.0;
  try {
    StandardParticleFilter pf(options, 1);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("process_noise.rotation"), std::string::npos);
  }
}

// A measurement far outside the cloud makes every likelihood underflow to zero in linear terms;
// log-domain weights keep the ratios, and the estimate stays finite.
TEST(StandardParticleFilter, WildMeasurementKeepsEstimatesFinite) {
  PoseParticleFilterOptions options;
  options.translation_particles = options.rotation_particles = 1000;
  StandardParticleFilter pf(options, 2);
  pf.initialise(0.0, make_pose({0, 0, 0}, Eigen::Quaterniond::Identity()));
  const auto far = make_pose({1000.0, -1000.0, 50.0}, so3::exp(Eigen::Vector3d(0, 3.0, 0)));
  const Estimate e = pf.step(kDt, &far, no_ensemble());
  for (double v : e.pose.mean.asVectorVal()) EXPECT_TRUE(std::isfinite(v));
  for (int i = 0; i < 36; ++i) EXPECT_TRUE(std::isfinite(e.pose.cov.data()[i]));
  EXPECT_EQ(e.recovery, RecoveryEvents{.sensor_reset = true});
}

// A PF settled on a static object at the origin (1000 + 1000 particles, seeded), for the
// recovery tests: returns the filter after 10 frames of exact measurements, none of them rescued.
StandardParticleFilter settled_filter(double reset_gate) {
  PoseParticleFilterOptions options;
  options.translation_particles = options.rotation_particles = 1000;
  options.reset_gate = reset_gate;
  StandardParticleFilter pf(options, 5);
  const auto origin = make_pose({0, 0, 0}, Eigen::Quaterniond::Identity());
  pf.initialise(0.0, origin);
  for (int k = 1; k <= 10; ++k) {
    const Estimate e = pf.step(k * kDt, &origin, no_ensemble());
    EXPECT_FALSE(e.recovery.any()) << mode_column(e.mode, e.recovery);
  }
  return pf;
}

// A detection 1 m off (200 sigmas, past the 5-sigma gate) re-scatters the translation particles
// around it: the mean of 1000 draws of N(z, 0.01^2) per axis is within 5 standard errors
// (5 * 0.01 / sqrt(1000) = 1.6 mm per axis, 2.7 mm in norm) of z. The rotation is untouched.
TEST(StandardParticleFilter, AMeasurementPastTheResetGateIsReportedAsAReset) {
  StandardParticleFilter pf = settled_filter(5.0);
  const auto jumped = make_pose({1.0, 0, 0}, Eigen::Quaterniond::Identity());
  const Estimate e = pf.step(11 * kDt, &jumped, no_ensemble());
  EXPECT_EQ(e.recovery, RecoveryEvents{.sensor_reset = true});
  EXPECT_EQ(mode_column(e.mode, e.recovery), "measured+reset");
  EXPECT_LT(translation_error(e.pose.mean, jumped), 0.0027);
  const auto next = pf.step(12 * kDt, &jumped, no_ensemble());
  EXPECT_FALSE(next.recovery.any());
}

// With sensor resetting off, the same detection 1 m off has likelihood exp(-0.5 (1 / 0.01)^2) =
// exp(-5000) under every particle, far below the smallest double. The log-domain weights keep
// the ratios (the particles on the near side of the cloud win), so the estimate moves only
// within the cloud (its spread is about 0.05 * sqrt(1/30) ~ 1 cm per axis) and stays finite;
// 0.3 m off (exp(-450) at most) is representable and is not reported.
TEST(StandardParticleFilter, WithoutTheGateAWildMeasurementIsReportedAsUnderflow) {
  StandardParticleFilter pf = settled_filter(0.0);
  const auto near = make_pose({0.3, 0, 0}, Eigen::Quaterniond::Identity());
  const Estimate ok = pf.step(11 * kDt, &near, no_ensemble());
  EXPECT_FALSE(ok.recovery.any()) << mode_column(ok.mode, ok.recovery);

  StandardParticleFilter wild_pf = settled_filter(0.0);
  const auto wild = make_pose({1.0, 0, 0}, Eigen::Quaterniond::Identity());
  const Estimate e = wild_pf.step(11 * kDt, &wild, no_ensemble());
  EXPECT_EQ(mode_column(e.mode, e.recovery), "measured+underflow");
  EXPECT_FALSE(wild_pf.last_report().weights_recovered);  // ratios kept, not reset
  const double moved = translation_of(e.pose.mean).x();
  EXPECT_GT(moved, 0.0);  // towards the measurement
  EXPECT_LT(moved, 0.05);
  EXPECT_TRUE(e.pose.cov.asEigen().allFinite());
}

// A detection so far off that d^2 overflows (1e200 m) gives every particle a log-weight of -inf:
// no weight is usable, so the weights are reset to uniform and the estimate is the prediction
// (within the cloud's spread of the origin), reported as underflow; never NaN.
TEST(StandardParticleFilter, ANonFiniteLikelihoodResetsTheWeightsAndIsReported) {
  StandardParticleFilter pf = settled_filter(0.0);
  const auto absurd = make_pose({1e200, 0, 0}, Eigen::Quaterniond::Identity());
  const Estimate e = pf.step(11 * kDt, &absurd, no_ensemble());
  EXPECT_TRUE(pf.last_report().weights_recovered);
  EXPECT_EQ(mode_column(e.mode, e.recovery), "measured+underflow");
  EXPECT_LT(translation_of(e.pose.mean).norm(), 0.01);
  EXPECT_TRUE(e.pose.cov.asEigen().allFinite());
}

}  // namespace
}  // namespace opf
