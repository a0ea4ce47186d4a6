#include "opf/estimators/random_walk_oapf.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/so3.h"
#include "opf/particles/gaussian_likelihood.h"
#include "opf/particles/particle_statistics.h"
#include "opf/particles/random_walk_model.h"
#include "opf/particles/resampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace opf {
namespace {

void require(bool ok, const char* name, const char* expectation, double value) {
  if (ok) return;
  std::ostringstream msg;
  msg << "oapf option " << name << " must be " << expectation << ", got " << value;
  throw std::invalid_argument(msg.str());
}

/// Log transition probabilities of the occlusion chain over one step.
struct ChainStep {
  double stay_visible;
  double to_occluded;
  double to_visible;
  double stay_occluded;
};

ChainStep chain_step(const OcclusionAwarePfOptions& options, double dt) {
  // Exact transition of the continuous-time chain: consecutive steps compose, so a log with
  // uneven frame intervals sees the same switching per second as an even one.
  const double a = options.occlusion_rate;
  const double b = options.reappearance_rate;
  const double relaxed = -std::expm1(-(a + b) * dt);
  const double p01 = a / (a + b) * relaxed;
  const double p10 = b / (a + b) * relaxed;
  return {std::log1p(-p01), std::log(p01), std::log(p10), std::log1p(-p10)};
}

template <int Dim>
void reset(OccludablePortion<Dim>& portion, std::size_t count) {
  portion.particles.resize(count);
  portion.occluded.assign(count, 0);
  portion.time_occluded = Eigen::VectorXd::Zero(Eigen::Index(count));
}

/// Per-particle random-walk spread over dt: occluded particles search wider the longer they hide.
template <int Dim>
Eigen::VectorXd step_spreads(const OccludablePortion<Dim>& portion, double density, double dt,
                             double growth) {
  const double base = density * std::sqrt(dt);
  Eigen::VectorXd sigma(portion.time_occluded.size());
  for (Eigen::Index i = 0; i < sigma.size(); ++i)
    sigma[i] =
        portion.occluded[std::size_t(i)] ? base * (1.0 + growth * portion.time_occluded[i]) : base;
  return sigma;
}

/// The exponent of paper Eq. 5 per particle, the standard PF's own, so both filters score a
/// visible particle identically.
template <int Dim, class Measurement>
Eigen::VectorXd visible_exponents(const ParticlePortion<Dim>& particles,
                                  const Measurement& measurement, double variance) {
  Eigen::VectorXd exponents;
  gaussian_exponents(particles, measurement, variance, exponents);
  return exponents;
}

/// Draws every particle's flag from its posterior given its previous flag, the chain and the two
/// likelihoods, multiplies its weight by the flag-marginal likelihood and advances its time
/// occluded. Returns each particle's posterior probability of being occluded.
template <int Dim>
Eigen::VectorXd update_flags(OccludablePortion<Dim>& portion,
                             const Eigen::VectorXd& visible_log_likelihood,
                             double occluded_log_likelihood, const ChainStep& chain, double dt,
                             Random& random) {
  Eigen::VectorXd& log_w = portion.particles.weights.log();
  Eigen::VectorXd occluded_posterior(log_w.size());
  for (Eigen::Index i = 0; i < log_w.size(); ++i) {
    const std::size_t k = std::size_t(i);
    const bool was_occluded = portion.occluded[k] != 0;
    const double visible =
        (was_occluded ? chain.to_visible : chain.stay_visible) + visible_log_likelihood[i];
    const double occluded =
        (was_occluded ? chain.stay_occluded : chain.to_occluded) + occluded_log_likelihood;
    // The occluded term is always finite (positive rates, dt > 0), so the log-sum-exp is too.
    const double top = std::max(visible, occluded);
    const double marginal = top + std::log(std::exp(visible - top) + std::exp(occluded - top));
    occluded_posterior[i] = std::exp(occluded - marginal);
    log_w[i] += marginal;
    const bool occluded_now = random.uniform() < occluded_posterior[i];
    portion.occluded[k] = occluded_now ? 1 : 0;
    portion.time_occluded[i] = occluded_now ? portion.time_occluded[i] + dt : 0.0;
  }
  return occluded_posterior;
}

/// Normalises the weights, returns the weighted probability of occlusion, and resamples states,
/// flags and times occluded together when the options ask for it.
template <int Dim>
double normalise_and_resample(OccludablePortion<Dim>& portion,
                              const Eigen::VectorXd& occluded_posterior,
                              const ResamplingOptions& options, Random& random, double& ess,
                              bool& resampled, bool& recovered) {
  recovered = !portion.particles.weights.normalise();
  const Eigen::VectorXd w = portion.particles.weights.linear();
  // Weighting the posterior flag probabilities, not the drawn flags, removes the draw's noise.
  const double occlusion = w.dot(occluded_posterior);
  ess = portion.particles.weights.effective_sample_fraction();
  resampled = should_resample(options, ess);
  if (resampled) {
    const std::vector<std::size_t> indices =
        resample_indices(w, portion.particles.size(), options.scheme, random);
    portion.particles.resample(indices);  // also checks the indices
    std::vector<std::uint8_t> occluded(indices.size());
    Eigen::VectorXd time_occluded(Eigen::Index(indices.size()));
    for (std::size_t k = 0; k < indices.size(); ++k) {
      occluded[k] = portion.occluded[indices[k]];
      time_occluded[Eigen::Index(k)] = portion.time_occluded[Eigen::Index(indices[k])];
    }
    portion.occluded = std::move(occluded);
    portion.time_occluded = std::move(time_occluded);
  }
  return occlusion;
}

}  // namespace

void validate(const OcclusionAwarePfOptions& options) {
  validate(options.particles);
  require(options.occlusion_rate > 0.0 && std::isfinite(options.occlusion_rate), "occlusion_rate",
          "a positive number (1/s)", options.occlusion_rate);
  require(options.reappearance_rate > 0.0 && std::isfinite(options.reappearance_rate),
          "reappearance_rate", "a positive number (1/s)", options.reappearance_rate);
  require(options.miss_probability > 0.0 && options.miss_probability <= 1.0, "miss_probability",
          "in (0, 1]", options.miss_probability);
  require(
      options.occluded_likelihood_sigmas > 0.0 && std::isfinite(options.occluded_likelihood_sigmas),
      "occluded_likelihood_sigmas", "a positive number", options.occluded_likelihood_sigmas);
  require(options.spread_growth >= 0.0 && std::isfinite(options.spread_growth), "spread_growth",
          "a non-negative number (1/s)", options.spread_growth);
}

OcclusionAwareParticleFilter::OcclusionAwareParticleFilter(const OcclusionAwarePfOptions& options,
                                                           std::uint64_t seed)
    : options_(options), random_(seed), noise_(derive_seed(seed, 1)) {
  validate(options_);
  reset(translation_, options_.particles.translation_particles);
  reset(rotation_, options_.particles.rotation_particles);
}

Estimate OcclusionAwareParticleFilter::initialise(double t, const mrpt::poses::CPose3D& first) {
  const PoseParticleFilterOptions& p = options_.particles;
  reset(translation_, p.translation_particles);
  reset(rotation_, p.rotation_particles);
  scatter_around(translation_.particles, translation_of(first), p.observation_noise_translation,
                 noise_);
  scatter_around(rotation_.particles, orientation_of(first), p.observation_noise_rotation, noise_);
  translation_occlusion_ = rotation_occlusion_ = 0.0;  // just detected: visible
  last_t_ = t;
  initialised_ = true;
  last_report_ = {};
  return make_estimate(t, EstimateMode::kMeasured);
}

Estimate OcclusionAwareParticleFilter::step(double t, const mrpt::poses::CPose3D* measurement,
                                            const EnsembleView& /*ensemble*/) {
  if (!initialised_) throw std::logic_error("OcclusionAwareParticleFilter::step before initialise");
  if (!(t > last_t_)) {
    std::ostringstream msg;
    msg << "OcclusionAwareParticleFilter: time " << t << " s does not follow " << last_t_ << " s";
    throw std::invalid_argument(msg.str());
  }
  const double dt = t - last_t_;
  last_t_ = t;
  const PoseParticleFilterOptions& p = options_.particles;

  // Motion uses the flags and times occluded of the previous step; the chain then moves the flags.
  predict_random_walk(
      translation_.particles,
      step_spreads(translation_, p.process_noise_translation, dt, options_.spread_growth), noise_);
  predict_random_walk(rotation_.particles,
                      step_spreads(rotation_, p.process_noise_rotation, dt, options_.spread_growth),
                      noise_);

  const ChainStep chain = chain_step(options_, dt);
  Eigen::VectorXd translation_visible, rotation_visible;
  double occluded_log_likelihood = 0.0;
  RecoveryEvents recovery;
  if (measurement) {
    const double sigma_t = p.observation_noise_translation;
    const double sigma_r = p.observation_noise_rotation;
    translation_visible =
        visible_exponents(translation_.particles, translation_of(*measurement), sigma_t * sigma_t);
    rotation_visible =
        visible_exponents(rotation_.particles, orientation_of(*measurement), sigma_r * sigma_r);
    // Sensor resetting, as in every particle estimator here (PoseParticleFilterOptions).
    const double gate = -0.5 * p.reset_gate * p.reset_gate;
    if (p.reset_gate > 0.0 && translation_visible.maxCoeff() < gate) {
      reset(translation_, translation_.particles.size());
      scatter_around(translation_.particles, translation_of(*measurement), sigma_t, noise_);
      translation_visible = visible_exponents(translation_.particles, translation_of(*measurement),
                                              sigma_t * sigma_t);
      recovery.sensor_reset = true;
    }
    if (p.reset_gate > 0.0 && rotation_visible.maxCoeff() < gate) {
      reset(rotation_, rotation_.particles.size());
      scatter_around(rotation_.particles, orientation_of(*measurement), sigma_r, noise_);
      rotation_visible =
          visible_exponents(rotation_.particles, orientation_of(*measurement), sigma_r * sigma_r);
      recovery.sensor_reset = true;
    }
    const double k = options_.occluded_likelihood_sigmas;
    occluded_log_likelihood = -0.5 * k * k;
  } else {
    const double miss = std::log(options_.miss_probability);
    translation_visible = Eigen::VectorXd::Constant(translation_.time_occluded.size(), miss);
    rotation_visible = Eigen::VectorXd::Constant(rotation_.time_occluded.size(), miss);
  }
  const Eigen::VectorXd translation_posterior =
      update_flags(translation_, translation_visible, occluded_log_likelihood, chain, dt, random_);
  const Eigen::VectorXd rotation_posterior =
      update_flags(rotation_, rotation_visible, occluded_log_likelihood, chain, dt, random_);

  ResampleReport report;
  bool translation_recovered = false, rotation_recovered = false;
  translation_occlusion_ = normalise_and_resample(
      translation_, translation_posterior, p.resampling, random_, report.ess_translation,
      report.resampled_translation, translation_recovered);
  rotation_occlusion_ =
      normalise_and_resample(rotation_, rotation_posterior, p.resampling, random_,
                             report.ess_rotation, report.resampled_rotation, rotation_recovered);
  report.weights_recovered = translation_recovered || rotation_recovered;
  last_report_ = report;
  // Occluded particles keep a finite likelihood, so only weights that are all non-finite (a reset
  // to uniform) count as underflow here.
  recovery.weights_underflow = report.weights_recovered;
  return make_estimate(t, measurement ? EstimateMode::kMeasured : EstimateMode::kRandomWalk,
                       recovery);
}

Estimate OcclusionAwareParticleFilter::make_estimate(double t, EstimateMode mode,
                                                     RecoveryEvents recovery) const {
  const TranslationMoments tm = translation_moments(translation_.particles);
  const RotationMoments rm = rotation_moments(rotation_.particles);
  const double sigma_t = options_.particles.observation_noise_translation;
  const double sigma_r = options_.particles.observation_noise_rotation;
  Estimate estimate;
  estimate.t = t;
  estimate.pose = make_pose_pdf(tm.mean, tm.covariance, rm.mean, rm.tangent_covariance);
  // Q is fixed: an occluded particle's constant likelihood does not inflate it.
  estimate.observation_trace = 3.0 * (sigma_t * sigma_t + sigma_r * sigma_r);
  estimate.mode = mode;
  estimate.recovery = recovery;
  estimate.occlusion_probability = translation_occlusion_;
  return estimate;
}

}  // namespace opf
