#include "opf/estimators/random_walk_oapf.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/so3.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace opf {
namespace {

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

/// Per-particle random-walk spread over dt: occluded particles search wider the longer they hide.
template <int Dim>
Eigen::VectorXd step_spreads(const ParticlePortion<Dim>& portion, double density, double dt,
                             double growth) {
  using Column = OcclusionAwareParticleFilter::Column;
  const double base = density * std::sqrt(dt);
  const auto occluded = portion.columns.row(Column::kOccluded);
  const auto time_occluded = portion.columns.row(Column::kTimeOccluded);
  Eigen::VectorXd sigma(portion.columns.cols());
  for (Eigen::Index i = 0; i < sigma.size(); ++i)
    sigma[i] = occluded[i] != 0.0 ? base * (1.0 + growth * time_occluded[i]) : base;
  return sigma;
}

/// Draws every particle's flag from its posterior given its previous flag, the chain and the two
/// likelihoods, advances its time occluded and keeps its posterior probability of occlusion.
/// Returns each particle's flag-marginal log-likelihood, its weight's factor.
template <int Dim>
Eigen::VectorXd update_flags(ParticlePortion<Dim>& portion,
                             const Eigen::VectorXd& visible_log_likelihood,
                             double occluded_log_likelihood, const ChainStep& chain, double dt,
                             Random& random) {
  using Column = OcclusionAwareParticleFilter::Column;
  auto occluded_flag = portion.columns.row(Column::kOccluded);
  auto time_occluded = portion.columns.row(Column::kTimeOccluded);
  auto occluded_posterior = portion.columns.row(Column::kOccludedPosterior);
  Eigen::VectorXd marginals(portion.columns.cols());
  for (Eigen::Index i = 0; i < marginals.size(); ++i) {
    const bool was_occluded = occluded_flag[i] != 0.0;
    const double visible =
        (was_occluded ? chain.to_visible : chain.stay_visible) + visible_log_likelihood[i];
    const double occluded =
        (was_occluded ? chain.stay_occluded : chain.to_occluded) + occluded_log_likelihood;
    // The occluded term is always finite (positive rates, dt > 0), so the log-sum-exp is too.
    const double top = std::max(visible, occluded);
    const double marginal = top + std::log(std::exp(visible - top) + std::exp(occluded - top));
    occluded_posterior[i] = std::exp(occluded - marginal);
    marginals[i] = marginal;
    const bool occluded_now = random.uniform() < occluded_posterior[i];
    occluded_flag[i] = occluded_now ? 1.0 : 0.0;
    time_occluded[i] = occluded_now ? time_occluded[i] + dt : 0.0;
  }
  return marginals;
}

}  // namespace

void validate(const OcclusionAwarePfOptions& options) {
  validate(options.particles);
  check_options(options, "oapf");
}

OcclusionAwareParticleFilter::OcclusionAwareParticleFilter(const OcclusionAwarePfOptions& options,
                                                           std::uint64_t seed)
    : options_(options), filter_(options.particles, seed) {
  validate(options_);
  filter_.translation().columns.setZero(kColumns, Eigen::Index(filter_.translation().size()));
  filter_.rotation().columns.setZero(kColumns, Eigen::Index(filter_.rotation().size()));
}

Estimate OcclusionAwareParticleFilter::initialise(double t, const mrpt::poses::CPose3D& first) {
  filter_.initialise(translation_of(first), orientation_of(first));
  filter_.translation().columns.setZero();  // just detected: visible
  filter_.rotation().columns.setZero();
  translation_occlusion_ = rotation_occlusion_ = 0.0;
  last_t_ = t;
  initialised_ = true;
  last_report_ = {};
  return make_estimate(t, EstimateMode::kMeasured);
}

Estimate OcclusionAwareParticleFilter::step(double t, const mrpt::poses::CPose3D* measurement,
                                            const EnsembleView& ensemble) {
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
  filter_.predict_per_particle(
      step_spreads(filter_.translation(), p.process_noise_translation, dt, options_.spread_growth),
      step_spreads(filter_.rotation(), p.process_noise_rotation, dt, options_.spread_growth));

  const ChainStep chain = chain_step(options_, dt);
  Eigen::VectorXd translation_visible, rotation_visible;
  double occluded_log_likelihood = 0.0;
  RecoveryEvents recovery;
  if (measurement) {
    const Eigen::Vector3d position = translation_of(*measurement);
    const Eigen::Quaterniond orientation = orientation_of(*measurement);
    filter_.set_translation_extra_noise(stated_extra_noise(ensemble, measurement));
    // Visible particles score Eq. 5 exactly as the standard PF's do.
    translation_visible = filter_.translation_exponents(position);
    rotation_visible = filter_.rotation_exponents(orientation);
    // Sensor resetting, as in every particle estimator here; a re-scattered particle is visible.
    const PortionsReset reset = filter_.reset_unreached(
        position, orientation, translation_visible.maxCoeff(), rotation_visible.maxCoeff());
    if (reset.translation) translation_visible = filter_.translation_exponents(position);
    if (reset.rotation) rotation_visible = filter_.rotation_exponents(orientation);
    recovery.sensor_reset = reset.any();
    const double k = options_.occluded_likelihood_sigmas;
    occluded_log_likelihood = -0.5 * k * k;
  } else {
    const double miss = std::log(options_.miss_probability);
    translation_visible =
        Eigen::VectorXd::Constant(Eigen::Index(filter_.translation().size()), miss);
    rotation_visible = Eigen::VectorXd::Constant(Eigen::Index(filter_.rotation().size()), miss);
  }
  Random& random = filter_.random();
  filter_.reweight_translation_by(update_flags(filter_.translation(), translation_visible,
                                               occluded_log_likelihood, chain, dt, random));
  filter_.reweight_rotation_by(update_flags(filter_.rotation(), rotation_visible,
                                            occluded_log_likelihood, chain, dt, random));

  last_report_ = filter_.normalise_and_resample();
  // Weighting the posterior flag probabilities, not the drawn flags, removes the draw's noise.
  translation_occlusion_ = last_report_.translation_column_means[kOccludedPosterior];
  rotation_occlusion_ = last_report_.rotation_column_means[kOccludedPosterior];
  // Occluded particles keep a finite likelihood, so only weights that are all non-finite (a reset
  // to uniform) count as underflow here.
  recovery.weights_underflow = last_report_.weights_recovered;
  return make_estimate(t, measurement ? EstimateMode::kMeasured : EstimateMode::kRandomWalk,
                       recovery);
}

Estimate OcclusionAwareParticleFilter::make_estimate(double t, EstimateMode mode,
                                                     RecoveryEvents recovery) const {
  Estimate estimate;
  estimate.t = t;
  estimate.pose = filter_.estimate();
  // Q is fixed: an occluded particle's constant likelihood does not inflate it.
  estimate.observation_trace = filter_.observation_trace();
  estimate.mode = mode;
  estimate.recovery = recovery;
  return estimate;
}

}  // namespace opf
