// The pose particle filter's steps for estimators with a per-particle state of their own:
// columns carried through normalise-and-resample and summarised before it, sensor resetting on
// given exponents, per-particle spreads, the estimator's own likelihood, the Gaussian posterior
// where a measurement falls in the cloud's far tail, a likelihood with a noise per axis.

#include "opf/particles/pose_particle_filter.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace opf {
namespace {

PoseParticleFilter small_filter(std::size_t n) {
  PoseParticleFilterOptions options;
  options.translation_particles = n;
  options.rotation_particles = n;
  PoseParticleFilter filter(options, 7);
  filter.initialise(Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Quaterniond::Identity());
  return filter;
}

TEST(PoseParticleFilter, ColumnMeansAreTakenUnderTheWeightsBeforeResampling) {
  PoseParticleFilter filter = small_filter(4);
  TranslationParticles& portion = filter.translation();
  portion.columns.resize(1, 4);
  portion.columns << 0.0, 1.0, 0.0, 1.0;
  const TranslationParticles::States before = portion.states;
  filter.reweight_translation_by(Eigen::Vector4d(0.1, 0.2, 0.3, 0.4).array().log().matrix());
  const ResampleReport report = filter.normalise_and_resample();
  ASSERT_EQ(report.translation_column_means.size(), 1);
  EXPECT_NEAR(report.translation_column_means[0], 0.2 + 0.4, 1e-15);
  EXPECT_EQ(report.rotation_column_means.size(), 0);  // no columns, no means
  ASSERT_TRUE(report.resampled_translation);
  // Each resampled particle kept its own column: its state names the particle it came from.
  for (Eigen::Index k = 0; k < 4; ++k) {
    Eigen::Index origin = -1;
    for (Eigen::Index i = 0; i < 4; ++i)
      if (before.col(i) == portion.states.col(k)) origin = i;
    ASSERT_GE(origin, 0) << "particle " << k;
    EXPECT_EQ(portion.columns(0, k), origin % 2 == 1 ? 1.0 : 0.0) << "particle " << k;
  }
}

TEST(PoseParticleFilter, ResetUnreachedScattersOnlyThePortionBeyondTheGate) {
  PoseParticleFilter filter = small_filter(500);
  filter.translation().columns.setConstant(1, 500, 7.0);
  filter.rotation().columns.setConstant(1, 500, 7.0);
  const RotationParticles::States rotation_before = filter.rotation().states;
  const Eigen::Vector3d far(2.0, 0.0, 0.0);
  // Gate 5 sigmas: -12.5 is the threshold; the translation's best is beyond, the rotation's not.
  const PortionsReset reset =
      filter.reset_unreached(far, Eigen::Quaterniond::Identity(), -12.6, -12.4);
  EXPECT_TRUE(reset.translation);
  EXPECT_FALSE(reset.rotation);
  const double sigma = filter.options().observation_noise_translation;
  // Scattered about the measurement: the mean within 5 standard errors of a 3-D mean of 500.
  EXPECT_LT((filter.translation_moments().mean - far).norm(),
            5.0 * std::sqrt(3.0) * sigma / std::sqrt(500.0));
  EXPECT_EQ(filter.translation().columns.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_TRUE(filter.translation().weights.uniform());
  EXPECT_EQ(filter.rotation().states, rotation_before);
  EXPECT_EQ(filter.rotation().columns.minCoeff(), 7.0);
}

TEST(PoseParticleFilter, PerParticleSpreadsMoveEachParticleByItsOwn) {
  PoseParticleFilter filter = small_filter(4);
  const TranslationParticles::States before = filter.translation().states;
  const RotationParticles::States rotation_before = filter.rotation().states;
  filter.predict_per_particle(Eigen::Vector4d(0.0, 0.0, 0.5, 0.5), Eigen::Vector4d::Zero());
  EXPECT_EQ(filter.translation().states.col(0), before.col(0));
  EXPECT_EQ(filter.translation().states.col(1), before.col(1));
  EXPECT_NE(filter.translation().states.col(2), before.col(2));
  EXPECT_NE(filter.translation().states.col(3), before.col(3));
  // A zero rotation step leaves the quaternions but for float rounding.
  EXPECT_TRUE(filter.rotation().states.isApprox(rotation_before, 1e-6f));
}

TEST(PoseParticleFilter, ExponentsAreTheUpdatesOwn) {
  // reweight() adds exactly translation_exponents(): an estimator building its likelihood on them
  // scores a particle as the standard PF does.
  PoseParticleFilter a = small_filter(64), b = small_filter(64);
  const Eigen::Vector3d z(0.11, 0.19, 0.31);
  a.reweight_translation(z);
  b.reweight_translation_by(b.translation_exponents(z));
  // The same weights (reweight() skips uniform weights' common offset, log N).
  const Eigen::VectorXd wa = a.translation().weights.linear(),
                        wb = b.translation().weights.linear();
  EXPECT_LT((wa - wb).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_GT(wa.maxCoeff(), 2.0 * wa.minCoeff());  // and the measurement did weigh the particles
}

// A cloud of 20 mm per axis (the spread a gap left) and a measurement 80 mm off along x, inside
// the 5-sigma reset gate of the 10 mm observation noise. The exact posterior is Gaussian: its
// mean 0.8 of the way to the measurement (gain 400 / (400 + 100)), 64 mm, and its spread
// sqrt(400 * 100 / 500) = 8.9 mm. Few of the 5000 particles lie there (3.2 sigmas out).
TEST(PoseParticleFilter, AMeasurementInTheCloudsFarTailTakesTheGaussianPosterior) {
  const Eigen::Vector3d prior(0.1, 0.2, 0.3), z = prior + Eigen::Vector3d(0.08, 0.0, 0.0);
  const auto widened = [&] {
    PoseParticleFilter filter = small_filter(5000);  // scattered with the 10 mm noise
    auto& states = filter.translation().states;
    const Eigen::Vector3d mean = filter.translation_moments().mean;
    states = ((states.colwise() - mean) * 2.0).colwise() + prior;
    return filter;
  };
  const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
  const double variance = widened().translation_moments().covariance(0, 0);
  ASSERT_NEAR(std::sqrt(variance), 0.02, 0.0005);
  const double noise = 0.01 * 0.01, gain = variance / (variance + noise);
  const double exact_mean = prior.x() + gain * 0.08, exact_sd = std::sqrt(variance * (1 - gain));

  // Reweighted, the few particles nearest the measurement fall short of the posterior and
  // report a spread much narrower than its (the failure this guards against).
  PoseParticleFilter reweighted = widened();
  EXPECT_FALSE(reweighted.update_with_measurement(z, identity, 0.0));
  EXPECT_FALSE(reweighted.translation_took_gaussian_posterior());
  reweighted.normalise_and_resample();
  const TranslationMoments short_of = reweighted.translation_moments();
  EXPECT_LT(short_of.mean.x(), exact_mean - 0.005);
  EXPECT_LT(std::sqrt(short_of.covariance(0, 0)), 0.7 * exact_sd);

  PoseParticleFilter gaussian = widened();
  EXPECT_FALSE(gaussian.update_with_measurement(z, identity, 0.01));
  EXPECT_TRUE(gaussian.translation_took_gaussian_posterior());
  EXPECT_FALSE(gaussian.translation_was_reset());
  EXPECT_TRUE(gaussian.translation().weights.uniform());
  gaussian.normalise_and_resample();
  const TranslationMoments posterior = gaussian.translation_moments();
  // The mean within 1 mm (about 0.3 mm of standard error: the prior's sampled moments and 5000
  // draws), the spread within 3% (1%), y and z where the prior had them.
  EXPECT_NEAR(posterior.mean.x(), exact_mean, 0.001);
  EXPECT_NEAR(std::sqrt(posterior.covariance(0, 0)), exact_sd, 0.03 * exact_sd);
  EXPECT_NEAR(posterior.mean.y(), prior.y(), 0.001);
  EXPECT_NEAR(posterior.mean.z(), prior.z(), 0.001);

  // A measurement the cloud covers is reweighted as always.
  PoseParticleFilter covered = widened();
  EXPECT_FALSE(covered.update_with_measurement(prior, identity, 0.01));
  EXPECT_FALSE(covered.translation_took_gaussian_posterior());
  EXPECT_FALSE(covered.translation().weights.uniform());
}

// The rotation's counterpart: a cloud of 0.1 rad per tangent axis and a measurement 0.3 rad off
// about x with 0.03 rad noise (its nearest particles well within the reset gate). The exact
// posterior's mean is 0.917 of the way (gain 0.01 / 0.0109), 0.275 rad, its spread sqrt(0.01 *
// 0.0009 / 0.0109) = 0.0287 rad per axis.
TEST(PoseParticleFilter, AnOrientationInTheCloudsFarTailTakesTheGaussianPosterior) {
  const Eigen::Vector3d origin(0.1, 0.2, 0.3);
  const Eigen::Quaterniond z = so3::exp(Eigen::Vector3d(0.3, 0.0, 0.0));
  const auto widened = [] {
    PoseParticleFilter filter = small_filter(5000);
    auto& states = filter.rotation().states;
    const Eigen::Matrix3d spread = filter.rotation_moments().tangent_covariance;
    const double scale = 0.1 / std::sqrt(spread.trace() / 3.0);
    for (Eigen::Index i = 0; i < states.cols(); ++i) {
      const Eigen::Quaterniond q(states(3, i), states(0, i), states(1, i), states(2, i));
      const Eigen::Quaterniond wide = so3::exp(scale * so3::log(q.normalized()));
      states.col(i) = wide.coeffs().cast<float>();
    }
    filter.set_rotation_likelihood_noise(0.03);
    return filter;
  };
  const double variance = widened().rotation_moments().tangent_covariance(0, 0);
  ASSERT_NEAR(std::sqrt(variance), 0.1, 0.003);
  const double noise = 0.03 * 0.03, gain = variance / (variance + noise);
  const double exact_angle = gain * 0.3, exact_sd = std::sqrt(variance * (1 - gain));

  // Reweighted, the few particles nearest the measurement report a spread much narrower than the
  // posterior's (0.58 of it).
  PoseParticleFilter reweighted = widened();
  reweighted.update_with_measurement(origin, z, 0.0);
  EXPECT_FALSE(reweighted.rotation_took_gaussian_posterior());
  reweighted.normalise_and_resample();
  const RotationMoments collapsed = reweighted.rotation_moments();
  EXPECT_LT(std::sqrt(collapsed.tangent_covariance(0, 0)), 0.8 * exact_sd);

  PoseParticleFilter gaussian = widened();
  EXPECT_FALSE(gaussian.update_with_measurement(origin, z, 0.01));
  EXPECT_TRUE(gaussian.rotation_took_gaussian_posterior());
  EXPECT_TRUE(gaussian.rotation().weights.uniform());
  gaussian.normalise_and_resample();
  const RotationMoments posterior = gaussian.rotation_moments();
  // The mean within 2 mrad (about 0.5 mrad of standard error: the prior's sampled moments and
  // 5000 draws), the spread within 3% (1%) per axis.
  const Eigen::Vector3d angle = so3::log(posterior.mean);
  EXPECT_NEAR(angle.x(), exact_angle, 0.002);
  EXPECT_NEAR(angle.y(), 0.0, 0.002);
  EXPECT_NEAR(angle.z(), 0.0, 0.002);
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_NEAR(std::sqrt(posterior.tangent_covariance(axis, axis)), exact_sd, 0.03 * exact_sd)
        << axis;

  // An orientation the cloud covers is reweighted as always.
  PoseParticleFilter covered = widened();
  covered.update_with_measurement(origin, Eigen::Quaterniond::Identity(), 0.01);
  EXPECT_FALSE(covered.rotation_took_gaussian_posterior());
  EXPECT_FALSE(covered.rotation().weights.uniform());
}

// The share test reads the same whether the prior's weights are known to be equal (every
// resampled frame: the likelihood's own weights are read) or are stored (their product with the
// likelihood is read): the same choice and, but for rounding, the same particles.
TEST(PoseParticleFilter, TheShareTestIsTheSameWithStoredEqualWeights) {
  const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
  const auto widened = [](bool stored) {
    PoseParticleFilter filter = small_filter(5000);
    auto& states = filter.translation().states;
    const Eigen::Vector3d mean = filter.translation_moments().mean;
    states = ((states.colwise() - mean) * 2.0).colwise() + mean;
    if (stored) filter.translation().weights.log();  // written out: no longer known equal
    return filter;
  };
  for (const double offset : {0.08, 0.0}) {
    PoseParticleFilter equal = widened(false), stored = widened(true);
    ASSERT_TRUE(equal.translation().weights.uniform());
    ASSERT_FALSE(stored.translation().weights.uniform());
    const Eigen::Vector3d z = equal.translation_moments().mean + Eigen::Vector3d(offset, 0, 0);
    EXPECT_EQ(equal.update_with_measurement(z, identity, 0.01),
              stored.update_with_measurement(z, identity, 0.01));
    EXPECT_EQ(equal.translation_took_gaussian_posterior(), offset > 0.0);
    EXPECT_EQ(stored.translation_took_gaussian_posterior(), offset > 0.0);
    equal.normalise_and_resample();
    stored.normalise_and_resample();
    EXPECT_LT((equal.translation().states - stored.translation().states).cwiseAbs().maxCoeff(),
              1e-12)
        << "offset " << offset;
  }
}

// The share test's relative weights are kept for the resampling that follows in the same step:
// it resamples as weights read afresh would, bit for bit; and a reweight in between (the weights
// moved on) is resampled by the new weights, not by the kept ones.
TEST(PoseParticleFilter, TheShareTestsWeightsResampleAsFreshOnesUnlessReweightedSince) {
  const Eigen::Quaterniond turned = so3::exp(Eigen::Vector3d(0.02, -0.01, 0.03));
  const Eigen::Vector3d z(0.11, 0.19, 0.3);  // well inside the cloud: no Gaussian update
  const Eigen::VectorXd tilt = Eigen::VectorXd::LinSpaced(2000, -3.0, 0.0);
  for (const bool reweighted_since : {false, true}) {
    PoseParticleFilter tested = small_filter(2000), fresh = small_filter(2000);
    tested.update_with_measurement(z, turned, 0.01);  // the share test, weights kept
    fresh.update_with_measurement(z, turned);         // no share test
    ASSERT_FALSE(tested.translation_took_gaussian_posterior());
    ASSERT_FALSE(tested.rotation_took_gaussian_posterior());
    if (reweighted_since) {
      tested.reweight_translation_by(tilt);
      tested.reweight_rotation_by(tilt);
      fresh.reweight_translation_by(tilt);
      fresh.reweight_rotation_by(tilt);
    }
    const ResampleReport a = tested.normalise_and_resample(), b = fresh.normalise_and_resample();
    EXPECT_EQ(a.ess_translation, b.ess_translation) << reweighted_since;
    EXPECT_EQ(a.ess_rotation, b.ess_rotation) << reweighted_since;
    EXPECT_EQ(tested.translation().states, fresh.translation().states) << reweighted_since;
    EXPECT_EQ(tested.rotation().states, fresh.rotation().states) << reweighted_since;
  }
}

// A step with a floor on its spread: with any floor under the random walk's the step is the random
// walk's, particle for particle (no floor at all, or half the walk); above it, each axis spreads
// by its own floor.
TEST(PoseParticleFilter, AStepSpreadsByItsFloorWhereThatIsWider) {
  const Eigen::Vector3d shift(0.01, 0.0, -0.02);
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitZ()));
  const double dt = 0.1, walk = 0.05 * 0.05 * dt;  // the default 0.05 m/sqrt(s), squared
  const double turn_walk = 0.1 * 0.1 * dt;         // the default 0.1 rad/sqrt(s), squared
  PoseParticleFilter walked = small_filter(5000), under = small_filter(5000),
                     over = small_filter(5000);
  walked.predict(dt, shift, turn, Eigen::Vector3d::Zero(), 0.0);
  under.predict(dt, shift, turn, Eigen::Vector3d::Constant(0.5 * walk), 0.5 * turn_walk);
  over.predict(dt, shift, turn, Eigen::Vector3d(0.5 * walk, 1.5 * walk, 0.5 * walk),
               1.5 * turn_walk);
  EXPECT_EQ(walked.translation().states, under.translation().states);
  EXPECT_EQ(walked.rotation().states, under.rotation().states);
  EXPECT_EQ(walked.translation().states.row(0), over.translation().states.row(0));
  EXPECT_NE(walked.translation().states.row(1), over.translation().states.row(1));
  EXPECT_NE(walked.rotation().states, over.rotation().states);

  PoseParticleFilter wide = small_filter(5000);
  const Eigen::Matrix3d before = wide.translation_moments().covariance;
  const RotationMoments rotation_before = wide.rotation_moments();
  const Eigen::Vector3d floor(0.04 * 0.04, walk, 0.0);
  wide.predict(dt, shift, turn, floor, 0.2 * 0.2);
  const Eigen::Matrix3d grown = wide.translation_moments().covariance - before;
  // Sample variances of 5000 draws: 2% standard error, 4 of them allowed (the initial cloud's
  // 10 mm adds to x's 40 mm in variance but is taken off with `before`).
  EXPECT_NEAR(grown(0, 0), floor.x(), 0.08 * floor.x());
  EXPECT_NEAR(grown(1, 1), walk, 0.08 * walk + 0.1 * before(1, 1));
  EXPECT_NEAR(grown(2, 2), walk, 0.08 * walk + 0.1 * before(2, 2));
  const double turned = wide.rotation_moments().tangent_covariance.trace() -
                        rotation_before.tangent_covariance.trace();
  EXPECT_NEAR(turned, 3.0 * 0.2 * 0.2, 0.1 * 3.0 * 0.2 * 0.2);
}

// A detector precise across the image (3 mm) and coarse in depth (10 mm), a cloud of 10 mm per axis
// and a measurement 6 mm off on every axis: the reweighted cloud's mean is the exact Gaussian
// posterior's, gains of 100 / 109 across and 1/2 in depth (5.5 and 3 mm), computed from the
// cloud's own sampled moments. About 700 of the 5000 particles stay effective: standard errors of
// 0.1 mm across and 0.3 mm in depth. The configured 10 mm on every axis moves x by 3 mm.
TEST(PoseParticleFilter, ALikelihoodWithANoisePerAxisTrustsEachAxisAsMuch) {
  PoseParticleFilter filter = small_filter(5000);
  const TranslationMoments prior = filter.translation_moments();
  const Eigen::Vector3d z = prior.mean + Eigen::Vector3d::Constant(0.006);
  const Eigen::Vector3d sigma(0.003, 0.003, 0.01);
  const Eigen::Matrix3d noise = sigma.cwiseAbs2().asDiagonal();
  const Eigen::Vector3d exact =
      prior.mean + prior.covariance * (prior.covariance + noise).ldlt().solve(z - prior.mean);
  ASSERT_NEAR(exact.x() - prior.mean.x(), 0.0055, 0.0003);
  ASSERT_NEAR(exact.z() - prior.mean.z(), 0.003, 0.0003);

  filter.set_translation_likelihood_noise(sigma);
  filter.reweight_translation(z);
  filter.normalise_and_resample();
  const Eigen::Vector3d mean = filter.translation_moments().mean;
  EXPECT_NEAR(mean.x(), exact.x(), 0.0005);
  EXPECT_NEAR(mean.y(), exact.y(), 0.0005);
  EXPECT_NEAR(mean.z(), exact.z(), 0.001);

  PoseParticleFilter configured = small_filter(5000);
  configured.reweight_translation(z);
  configured.normalise_and_resample();
  EXPECT_LT(configured.translation_moments().mean.x(), exact.x() - 0.0015);

  // The same noise on every axis is the configured likelihood, to the bit.
  PoseParticleFilter same = small_filter(64), plain = small_filter(64);
  same.set_translation_likelihood_noise(Eigen::Vector3d::Constant(0.01));
  EXPECT_EQ(same.translation_exponents(z), plain.translation_exponents(z));
  // A noise that is not positive on every axis is refused, naming the option.
  try {
    same.set_translation_likelihood_noise(Eigen::Vector3d(0.01, 0.0, 0.01));
    FAIL() << "a zero noise was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("observation_noise.translation"), std::string::npos)
        << e.what();
  }
}

// A cloud flat in z (every particle at the same height) has no Gaussian posterior to draw from
// (its covariance is singular): it is reweighted, and stays finite.
TEST(PoseParticleFilter, AFlatCloudInTheFarTailIsReweighted) {
  PoseParticleFilter filter = small_filter(5000);
  auto& states = filter.translation().states;
  states = (states * 2.0).eval();
  states.row(2).setConstant(0.3);
  const Eigen::Vector3d z = filter.translation_moments().mean + Eigen::Vector3d(0.08, 0.0, 0.0);
  filter.update_with_measurement(z, Eigen::Quaterniond::Identity(), 0.01);
  EXPECT_FALSE(filter.translation_took_gaussian_posterior());
  filter.normalise_and_resample();
  EXPECT_TRUE(filter.translation_moments().mean.allFinite());
  EXPECT_TRUE(filter.translation().states.allFinite());
}

}  // namespace
}  // namespace opf
