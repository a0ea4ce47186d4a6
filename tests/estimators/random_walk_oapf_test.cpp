#include "opf/estimators/random_walk_oapf.h"

#include "opf/core/metrics.h"
#include "opf/core/pose_conversion.h"
#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/estimators/standard_pf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace opf {
namespace {

constexpr double kDt = 1.0 / 30.0;
constexpr int kGapFrames = 30;  // one second unseen
// E||e|| of a 3-D isotropic Gaussian with per-axis std s is s * 2 sqrt(2/pi).
const double kChi3Mean = 2.0 * std::sqrt(2.0 / std::numbers::pi);

const EnsembleView& no_ensemble() {
  static const Frame frame;
  static const EnsembleView view{frame, {}};
  return view;
}

// Steady-state per-axis error variance of a random-walk Kalman filter (process variance q per
// step, measurement variance r) on a STATIC truth, as in the standard PF's test.
double static_truth_error_variance(double q, double r) {
  const double p = 0.5 * (-q + std::sqrt(q * q + 4.0 * q * r));
  const double gain = (p + q) / (p + q + r);
  return gain * r / (2.0 - gain);
}

// The occlusion chain's switching probabilities over dt (the exact continuous-time solution).
struct Switching {
  double to_occluded;
  double to_visible;
};
Switching switching(const OcclusionAwarePfOptions& o, double dt) {
  const double relaxed = -std::expm1(-(o.occlusion_rate + o.reappearance_rate) * dt);
  const double total = o.occlusion_rate + o.reappearance_rate;
  return {o.occlusion_rate / total * relaxed, o.reappearance_rate / total * relaxed};
}

// While the measurement is missing, the likelihood does not depend on the pose, so the weighted
// occlusion probability follows the two-state HMM filter exactly (up to Monte Carlo noise).
double next_gap_occlusion(double p, const Switching& s, double miss_probability) {
  const double predicted = p * (1.0 - s.to_visible) + (1.0 - p) * s.to_occluded;
  return predicted / (predicted + (1.0 - predicted) * miss_probability);
}

// Monte Carlo tolerance of a probability estimated from n flags: five binomial standard errors.
double flag_tolerance(double p, std::size_t n) {
  return 5.0 * std::sqrt(std::max(p * (1.0 - p), 1.0 / double(n)) / double(n));
}

// Noisy detections of a fixed orientation at a given position, noise as the filters' Q.
class Detector {
 public:
  Detector(std::uint64_t seed, const Eigen::Quaterniond& orientation, double sigma_t,
           double sigma_r)
      : noise_(seed), orientation_(orientation), sigma_t_(sigma_t), sigma_r_(sigma_r) {}
  mrpt::poses::CPose3D operator()(const Eigen::Vector3d& position) {
    const Eigen::Vector3d p = position + sigma_t_ * gaussian();
    return make_pose(p, orientation_ * so3::exp(sigma_r_ * gaussian()));
  }

 private:
  Eigen::Vector3d gaussian() { return {noise_.normal(), noise_.normal(), noise_.normal()}; }
  Random noise_;
  Eigen::Quaterniond orientation_;
  double sigma_t_, sigma_r_;
};

const Eigen::Quaterniond kOrientation = so3::exp(Eigen::Vector3d(0.2, -0.3, 1.0));

double translation_variance(const Estimate& e) {
  return (e.pose.cov(0, 0) + e.pose.cov(1, 1) + e.pose.cov(2, 2)) / 3.0;
}
double rotation_variance(const Estimate& e) {
  return (e.pose.cov(3, 3) + e.pose.cov(4, 4) + e.pose.cov(5, 5)) / 3.0;
}

// Measurements always present: the occlusion hypothesis never competes with a cloud on the truth,
// so the OAPF is the standard PF and meets the same derived Kalman steady state (+-15%, see the
// PF's test); on the very same measurement stream the two differ only by their Monte Carlo error,
// which is ~100 times smaller than the measurement-driven error, so their mean errors agree to 5%.
TEST(OcclusionAwareParticleFilter, TracksAStaticObjectAsWellAsTheStandardPf) {
  const OcclusionAwarePfOptions options;
  const Eigen::Vector3d truth_p(0.4, -0.1, 0.03);
  const mrpt::poses::CPose3D truth = make_pose(truth_p, kOrientation);
  OcclusionAwareParticleFilter oapf(options, 11);
  StandardParticleFilter pf(options.particles, 11);
  Detector detect(12, kOrientation, 0.01, 0.05);
  const auto first = detect(truth_p);
  oapf.initialise(0.0, first);
  pf.initialise(0.0, first);

  double oapf_t = 0.0, oapf_r = 0.0, pf_t = 0.0, max_occlusion = 0.0;
  constexpr int kBurnIn = 30, kFrames = 400;
  for (int k = 1; k <= kBurnIn + kFrames; ++k) {
    const auto z = detect(truth_p);
    const Estimate e = oapf.step(k * kDt, &z, no_ensemble());
    const Estimate b = pf.step(k * kDt, &z, no_ensemble());
    ASSERT_EQ(e.mode, EstimateMode::kMeasured);
    max_occlusion = std::max(max_occlusion, oapf.translation_occlusion_probability());
    if (k > kBurnIn) {
      oapf_t += translation_error(e.pose.mean, truth);
      oapf_r += rotation_error_geodesic(e.pose.mean, truth);
      pf_t += translation_error(b.pose.mean, truth);
    }
  }
  oapf_t /= kFrames;
  oapf_r /= kFrames;
  pf_t /= kFrames;
  const double expected_t =
      kChi3Mean * std::sqrt(static_truth_error_variance(0.05 * 0.05 * kDt, 0.01 * 0.01));
  const double expected_r =
      kChi3Mean * std::sqrt(static_truth_error_variance(0.1 * 0.1 * kDt, 0.05 * 0.05));
  EXPECT_NEAR(oapf_t, expected_t, 0.15 * expected_t);
  EXPECT_NEAR(oapf_r, expected_r, 0.15 * expected_r);
  EXPECT_NEAR(oapf_t / pf_t, 1.0, 0.05);
  // Every measurement within 5 sigma of the truth (all 430 with probability 0.994) favours a
  // visible particle over an occluded one by at least exp((k^2 - 5^2) / 2), so occlusion never
  // gets beyond one chain onset times that.
  const double k = options.occluded_likelihood_sigmas;
  EXPECT_LT(max_occlusion, switching(options, kDt).to_occluded * std::exp(-(k * k - 25.0) / 2.0));
}

// A one-second gap at the place the object vanished, then the object returns there.
TEST(OcclusionAwareParticleFilter, OcclusionProbabilityRisesThroughAGapAndFallsOnReturn) {
  const OcclusionAwarePfOptions options;
  const std::size_t n = options.particles.translation_particles;
  const Eigen::Vector3d position(0.5, 0.0, 0.1);
  OcclusionAwareParticleFilter oapf(options, 21);
  Detector detect(22, kOrientation, 0.01, 0.05);
  oapf.initialise(0.0, detect(position));
  int k = 1;
  Estimate e;
  for (; k <= 30; ++k) {
    const auto z = detect(position);
    e = oapf.step(k * kDt, &z, no_ensemble());
  }

  const Switching s = switching(options, kDt);
  double expected = oapf.translation_occlusion_probability();
  double previous = expected;
  for (int j = 1; j <= kGapFrames; ++j, ++k) {
    e = oapf.step(k * kDt, nullptr, no_ensemble());
    ASSERT_EQ(e.mode, EstimateMode::kRandomWalk);
    const double p = oapf.translation_occlusion_probability();
    expected = next_gap_occlusion(expected, s, options.miss_probability);
    EXPECT_NEAR(p, expected, flag_tolerance(expected, n)) << "gap frame " << j;
    EXPECT_GE(p, previous - flag_tolerance(p, n)) << "gap frame " << j;  // (nearly) monotonic
    previous = p;
    // Resampling moved the flags and times occluded with the states: only occluded particles have
    // been hiding, and none longer than the gap.
    const auto& columns = oapf.translation().columns;
    for (Eigen::Index i = 0; i < Eigen::Index(n); ++i) {
      const double tau = columns(OcclusionAwareParticleFilter::kTimeOccluded, i);
      if (columns(OcclusionAwareParticleFilter::kOccluded, i) != 0.0)
        ASSERT_TRUE(tau > 0.0 && tau <= j * kDt + 1e-12) << "particle " << i << " tau " << tau;
      else
        ASSERT_EQ(tau, 0.0) << "particle " << i;
    }
  }
  // The threshold: the HMM filter's value after one second, less the Monte Carlo tolerance. With
  // the defaults it is 0.996: each miss multiplies the odds of occlusion by 1/miss_probability
  // while the chain pulls back by the reappearance rate.
  EXPECT_GT(previous, expected - flag_tolerance(expected, n));
  EXPECT_GT(previous, 0.99);

  // Back where it vanished: the occlusion hypothesis explains the detection exp(-k^2/2) as well as
  // a particle on it. The broad cloud (per-axis variance V) puts an average visible likelihood of
  // (r^2 / (2 r^2 + V))^(3/2) ~ 1e-3 on it, reached by previously occluded particles with the chain
  // probability p10, so one frame leaves P <~ exp(-18) / (p10 1e-3) = 5e-4: assert < 0.01, the
  // margin for the few particles that carry that average. The second frame, with visible particles
  // within 3 sigma, multiplies the odds by at most exp(-(k^2 - 3^2) / 2) = 1.4e-6.
  const double kk = options.occluded_likelihood_sigmas;
  const auto z1 = detect(position);
  const Estimate back1 = oapf.step(k++ * kDt, &z1, no_ensemble());
  const double back1_occlusion = oapf.translation_occlusion_probability();
  const auto z2 = detect(position);
  oapf.step(k++ * kDt, &z2, no_ensemble());
  EXPECT_EQ(back1.mode, EstimateMode::kMeasured);
  EXPECT_LT(back1_occlusion, 0.01);
  EXPECT_LT(oapf.translation_occlusion_probability(), std::exp(-(kk * kk - 9.0) / 2.0));
}

// With uninformative misses (miss_probability = 1) the flags follow the chain alone, whose exact
// solution P(T) = a/(a+b) (1 - exp(-(a+b) T)) from P(0) ~ 0 must hold whatever the frame intervals.
TEST(OcclusionAwareParticleFilter, OcclusionChainIsIndependentOfTheFrameIntervals) {
  OcclusionAwarePfOptions options;
  options.miss_probability = 1.0;
  const std::size_t n = options.particles.translation_particles;
  for (const std::vector<double>& intervals :
       {std::vector<double>{1.0 / 30.0}, std::vector<double>{1.0 / 10.0, 1.0 / 60.0, 0.05}}) {
    OcclusionAwareParticleFilter oapf(options, 31);
    Detector detect(32, kOrientation, 0.01, 0.05);
    const Eigen::Vector3d position(0.1, 0.2, 0.3);
    oapf.initialise(0.0, detect(position));
    double t = 0.0;
    for (int k = 0; k < 10; ++k) {
      const auto z = detect(position);
      oapf.step(t += kDt, &z, no_ensemble());
    }
    const double start = t;
    Estimate e;
    for (std::size_t k = 0; t - start < 2.0 - 1e-9; ++k)
      e = oapf.step(t += intervals[k % intervals.size()], nullptr, no_ensemble());
    const double a = options.occlusion_rate, b = options.reappearance_rate;
    const double expected = a / (a + b) * -std::expm1(-(a + b) * (t - start));
    EXPECT_NEAR(oapf.translation_occlusion_probability(), expected, flag_tolerance(expected, n))
        << intervals.size() << " interval(s)";
  }
}

// During the gap a particle hidden since gap frame j has per-axis variance
// density^2 dt [j + sum_{m=1}^{M-j} (1 + g m dt)^2] after M frames (it moves as visible until
// its flag flips, then starts one frame hidden). The HMM says ~95% are hidden by frame 3, so the
// cloud's growth lies between the j = 3 value (x 0.95) and the j = 1 value; the standard PF grows
// by density^2 M dt. Each sample variance of 5000 particles is good to 2% (sqrt(2/5000)): allow 8%.
TEST(OcclusionAwareParticleFilter, SpreadGrowsFasterThanTheStandardPfThroughAGap) {
  const OcclusionAwarePfOptions options;
  const Eigen::Vector3d position(0.5, 0.0, 0.1);
  OcclusionAwareParticleFilter oapf(options, 41);
  StandardParticleFilter pf(options.particles, 41);
  Detector detect(42, kOrientation, 0.01, 0.05);
  const auto first = detect(position);
  oapf.initialise(0.0, first);
  pf.initialise(0.0, first);
  int k = 1;
  Estimate o, p;
  for (; k <= 30; ++k) {
    const auto z = detect(position);
    o = oapf.step(k * kDt, &z, no_ensemble());
    p = pf.step(k * kDt, &z, no_ensemble());
  }
  const double o_before = translation_variance(o), p_before = translation_variance(p);
  const double o_rot_before = rotation_variance(o), p_rot_before = rotation_variance(p);
  for (int j = 0; j < kGapFrames; ++j, ++k) {
    o = oapf.step(k * kDt, nullptr, no_ensemble());
    p = pf.step(k * kDt, nullptr, no_ensemble());
    ASSERT_EQ(o.mode, EstimateMode::kRandomWalk);
  }
  const double g = options.spread_growth;
  auto hidden_from = [&](int flip) {
    double sum = flip;
    for (int m = 1; m <= kGapFrames - flip; ++m) sum += std::pow(1.0 + g * m * kDt, 2);
    return sum * kDt;
  };
  const double density = options.particles.process_noise_translation;
  const double o_growth = translation_variance(o) - o_before;
  const double p_growth = translation_variance(p) - p_before;
  EXPECT_GT(o_growth, 0.92 * 0.95 * density * density * hidden_from(3));
  EXPECT_LT(o_growth, 1.08 * density * density * hidden_from(1));
  EXPECT_NEAR(p_growth, density * density * kGapFrames * kDt, 0.08 * (p_growth + p_before));
  // With the default growth 2/s that is >= 3.3 times the PF's.
  EXPECT_GT(o_growth, 0.92 * 0.95 * hidden_from(3) / (1.08 * kGapFrames * kDt) * p_growth);
  // The rotation portion widens its search the same way (yaw-pitch-roll ~ tangent near the mean).
  EXPECT_GT(rotation_variance(o) - o_rot_before, 2.0 * (rotation_variance(p) - p_rot_before));
}

// The object vanishes for one second and reappears 0.3 m away. The standard PF's cloud (per-axis
// sigma s = density sqrt(T) = 0.05 m) reaches about sqrt(2 ln N) s = 0.21 m toward it, and after
// that it creeps by about sqrt(2 ln N) density sqrt(dt) = 0.038 m a frame, so it needs ~3.4 frames
// to arrive. The OAPF's hidden particles spread to ~0.1 m, which puts the detection inside the
// cloud (2.9 sigma) where some occluded particle takes it up. So at N = 3 frames, the last before
// the PF can arrive, the OAPF's error must be below the PF's in every run and below 3.4 sigma,
// the 99% quantile of a single raw measurement's error: it has re-acquired. Both filters run
// without sensor resetting (reset_gate 0), which would re-scatter either cloud at once and hide
// the difference between the two searches.
TEST(OcclusionAwareParticleFilter, ReacquiresAnObjectThatReappearsElsewhereFasterThanThePf) {
  OcclusionAwarePfOptions options;
  options.particles.reset_gate = 0.0;
  const double sigma = options.particles.observation_noise_translation;
  constexpr int kN = 3;
  for (std::uint64_t run = 0; run < 4; ++run) {
    const Eigen::Vector3d vanished(0.4, 0.0, 0.0);
    const Eigen::Vector3d reappeared = vanished + Eigen::Vector3d(0.0, 0.3, 0.0);
    OcclusionAwareParticleFilter oapf(options, derive_seed(51, run));
    StandardParticleFilter pf(options.particles, derive_seed(51, run));
    Detector detect(derive_seed(52, run), kOrientation, 0.01, 0.05);
    const auto first = detect(vanished);
    oapf.initialise(0.0, first);
    pf.initialise(0.0, first);
    int k = 1;
    for (; k <= 30; ++k) {
      const auto z = detect(vanished);
      oapf.step(k * kDt, &z, no_ensemble());
      pf.step(k * kDt, &z, no_ensemble());
    }
    for (int j = 0; j < kGapFrames; ++j, ++k) {
      oapf.step(k * kDt, nullptr, no_ensemble());
      pf.step(k * kDt, nullptr, no_ensemble());
    }
    const mrpt::poses::CPose3D truth = make_pose(reappeared, kOrientation);
    Estimate o, p;
    for (int j = 0; j < kN; ++j, ++k) {
      const auto z = detect(reappeared);
      o = oapf.step(k * kDt, &z, no_ensemble());
      p = pf.step(k * kDt, &z, no_ensemble());
    }
    const double oapf_error = translation_error(o.pose.mean, truth);
    const double pf_error = translation_error(p.pose.mean, truth);
    EXPECT_LT(oapf_error, pf_error) << "run " << run;
    EXPECT_LT(oapf_error, 3.4 * sigma) << "run " << run;
  }
}

TEST(OcclusionAwareParticleFilter, SameSeedIsBitIdenticalDifferentSeedIsNot) {
  OcclusionAwarePfOptions options;
  options.particles.translation_particles = options.particles.rotation_particles = 500;
  auto run = [&](std::uint64_t seed) {
    OcclusionAwareParticleFilter oapf(options, seed);
    const auto z = make_pose({0.1, 0.2, 0.3}, so3::exp(Eigen::Vector3d(0.1, 0.2, 0.3)));
    oapf.initialise(0.0, z);
    Estimate e;
    std::vector<double> trace;
    for (int k = 1; k < 40; ++k) {
      e = oapf.step(k * kDt, k % 3 && (k < 15 || k > 30) ? &z : nullptr, no_ensemble());
      for (double v : e.pose.mean.asVectorVal()) trace.push_back(v);
      trace.push_back(oapf.translation_occlusion_probability());
      trace.push_back(e.pose.cov(0, 0));
    }
    return trace;
  };
  EXPECT_EQ(run(3), run(3));
  EXPECT_NE(run(3), run(4));
}

TEST(OcclusionAwareParticleFilter, RejectsBadOptionsNamingThem) {
  struct Case {
    std::function<void(OcclusionAwarePfOptions&)> spoil;
    const char* field;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Case& c : std::vector<Case>{
           {[](auto& o) { o.occlusion_rate = 0.0; }, "occlusion_rate"},
           {[&](auto& o) { o.occlusion_rate = nan; }, "occlusion_rate"},
           {[](auto& o) { o.reappearance_rate = -1.0; }, "reappearance_rate"},
           {[](auto& o) { o.miss_probability = 0.0; }, "miss_probability"},
           {[](auto& o) { o.miss_probability = 1.5; }, "miss_probability"},
           {[](auto& o) { o.occluded_likelihood_sigmas = 0.0; }, "occluded_likelihood_sigmas"},
           {[](auto& o) { o.spread_growth = -0.1; }, "spread_growth"},
           {[](auto& o) { o.particles.process_noise_translation = 0.0; },
            "process_noise.translation"},
       }) {
    OcclusionAwarePfOptions options;
    c.spoil(options);
    try {
      OcclusionAwareParticleFilter oapf(options, 1);
      ADD_FAILURE() << "expected std::invalid_argument for " << c.field;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(c.field), std::string::npos) << e.what();
    }
  }
  OcclusionAwarePfOptions edge;
  edge.miss_probability = 1.0;
  edge.spread_growth = 0.0;
  EXPECT_NO_THROW(validate(edge));
}

TEST(OcclusionAwareParticleFilter, RejectsTimeThatDoesNotAdvanceAndStepBeforeInitialise) {
  OcclusionAwareParticleFilter oapf(OcclusionAwarePfOptions{}, 1);
  const mrpt::poses::CPose3D z;
  EXPECT_THROW(oapf.step(1.0, &z, no_ensemble()), std::logic_error);
  oapf.initialise(1.0, z);
  EXPECT_EQ(oapf.translation_occlusion_probability(), 0.0);
  EXPECT_EQ(oapf.name(), "oapf");
  EXPECT_THROW(oapf.step(1.0, &z, no_ensemble()), std::invalid_argument);
  EXPECT_THROW(oapf.step(0.5, &z, no_ensemble()), std::invalid_argument);
}

}  // namespace
}  // namespace opf
