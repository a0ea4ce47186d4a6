#include "opf/particles/pose_particle_filter.h"

#include "opf/core/estimator.h"
#include "opf/core/pose_conversion.h"
#include "opf/core/so3.h"
#include "opf/particles/gaussian_likelihood.h"
#include "opf/particles/random_walk_model.h"
#include "opf/particles/resampling.h"
#include "opf/particles/weight_kernels.h"

#include <Eigen/Cholesky>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace opf {
namespace {

// The weight buffers are allocated per call rather than kept by the filter: freed and allocated
// again step after step, the same memory serves every filter on a thread and stays in cache.
template <int Dim>
bool normalise_and_maybe_resample(ParticlePortion<Dim>& portion, bool reweighted,
                                  const ResamplingOptions& options, Random& random, double& ess,
                                  bool& resampled, Eigen::VectorXd& column_means,
                                  KeptRelativeWeights& kept) {
  resampled = false;
  ess = 1.0;
  if (portion.weights.uniform()) {
    if (portion.columns.rows() > 0) column_means = portion.columns.rowwise().mean();
    return true;
  }
  const std::size_t n = portion.size();
  // A portion with columns takes the general path, whose indices move the columns too.
  if (reweighted && options.every_frame && portion.columns.rows() == 0 &&
      options.scheme == mrpt::bayes::CParticleFilter::prSystematic) {
    // Resampling follows at once (the paper's default): relative weights in single precision
    // are all it needs, and normalising the log-weights first would be undone by the reset.
    std::vector<float> relative;
    kernels::NormalisedWeights w;
    if (kept.hold_for(portion.weights)) {  // the share test's, this step
      relative.swap(kept.values);
      w = kept.found;
    } else {
      relative.resize(n);
      w = kernels::resampling_weights(portion.weights.log().data(), relative.data(), n);
    }
    resampled = true;
    if (!w.usable) {
      portion.weights.reset();  // uniform weights resample to the same particles
      return false;
    }
    ess = w.ess_fraction;
    portion.resample_systematic(relative, random.uniform());
    return true;
  }
  Eigen::VectorXd linear;
  const kernels::NormalisedWeights normalised = portion.weights.normalise(linear);
  if (normalised.usable) ess = normalised.ess_fraction;
  if (portion.columns.rows() > 0) column_means = portion.columns * linear;
  if (reweighted && should_resample(options, ess)) {
    portion.resample(resample_indices(linear, n, options.scheme, random));
    resampled = true;
  }
  return normalised.usable;
}

}  // namespace

void validate(const PoseParticleFilterOptions& options) {
  check_options(options, "particle filter");
}

PoseParticleFilter::PoseParticleFilter(const PoseParticleFilterOptions& options, std::uint64_t seed)
    : options_(options),
      translation_likelihood_noise_(
          Eigen::Vector3d::Constant(options.observation_noise_translation)),
      rotation_likelihood_noise_(options.observation_noise_rotation),
      random_(seed),
      noise_(derive_seed(seed, 1)) {
  validate(options_);
  translation_.resize(options_.translation_particles);
  rotation_.resize(options_.rotation_particles);
}

void PoseParticleFilter::reseed(std::uint64_t seed) {
  random_ = Random(seed);
  noise_ = GaussianSampler(derive_seed(seed, 1));
}

void PoseParticleFilter::initialise(const Eigen::Vector3d& position,
                                    const Eigen::Quaterniond& orientation) {
  scatter_around(translation_, position, options_.observation_noise_translation, noise_);
  scatter_around(rotation_, orientation, options_.observation_noise_rotation, noise_);
  translation_reweighted_ = rotation_reweighted_ = false;
  translation_underflow_ = rotation_underflow_ = false;
}

void PoseParticleFilter::predict(double dt) {
  predict_translation(dt);
  predict_rotation(dt);
}

void PoseParticleFilter::predict_translation(double dt) {
  if (!(dt >= 0.0)) throw std::invalid_argument("PoseParticleFilter::predict: negative dt");
  predict_random_walk(translation_, options_.process_noise_translation * std::sqrt(dt), noise_);
}

void PoseParticleFilter::predict_rotation(double dt) {
  if (!(dt >= 0.0)) throw std::invalid_argument("PoseParticleFilter::predict: negative dt");
  predict_random_walk(rotation_, options_.process_noise_rotation * std::sqrt(dt), noise_);
}

void PoseParticleFilter::set_rotation_likelihood_noise(double sigma) {
  OptionChecker("particle filter").number("observation_noise.rotation", sigma, positive());
  rotation_likelihood_noise_ = sigma;
}

void PoseParticleFilter::set_translation_likelihood_noise(const Eigen::Vector3d& sigma) {
  const OptionChecker check("particle filter");
  for (int axis = 0; axis < 3; ++axis)
    check.number("observation_noise.translation", sigma(axis), positive());
  translation_likelihood_noise_ = sigma;
}

void PoseParticleFilter::set_translation_extra_noise(double extra_noise) {
  set_translation_likelihood_noise(Eigen::Vector3d::Constant(
      observation_sigma(options_.observation_noise_translation, extra_noise)));
}

void PoseParticleFilter::predict_per_particle(const Eigen::VectorXd& translation_sigmas,
                                              const Eigen::VectorXd& rotation_sigmas) {
  predict_random_walk(translation_, translation_sigmas, noise_);
  predict_random_walk(rotation_, rotation_sigmas, noise_);
}

void PoseParticleFilter::predict(double dt, const Eigen::Vector3d& translation,
                                 const Eigen::Quaterniond& rotation,
                                 const Eigen::Vector3d& variance, double rotation_variance) {
  if (!(dt >= 0.0)) throw std::invalid_argument("PoseParticleFilter::predict: negative dt");
  const double walk = options_.process_noise_translation * std::sqrt(dt);
  const Eigen::Vector3d sigma = variance.cwiseMax(walk * walk).cwiseSqrt();
  predict_random_walk(translation_, sigma, translation, noise_);
  const double turn = options_.process_noise_rotation * std::sqrt(dt);
  predict_random_walk(rotation_, std::sqrt(std::max(turn * turn, rotation_variance)), rotation,
                      noise_);
}

void PoseParticleFilter::shift(const Eigen::Vector3d& translation,
                               const Eigen::Quaterniond& rotation) {
  // Row by row: each coordinate is contiguous (structure of arrays), so the add vectorises; a
  // column-wise add would step through the rows three doubles at a time.
  for (Eigen::Index k = 0; k < 3; ++k) translation_.states.row(k).array() += translation(k);
  rotate_all(rotation_, rotation);
}

void PoseParticleFilter::carry(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                               const Eigen::Quaterniond& rotation) {
  const Eigen::Matrix3d r = rotation.normalized().toRotationMatrix();
  translation_.states = (r * (translation_.states.colwise() - from)).colwise() + to;
  rotate_all(rotation_, rotation);
}

void PoseParticleFilter::diffuse(const Eigen::Vector3d& translation_sigma, double rotation_sigma) {
  if (!(translation_sigma.minCoeff() >= 0.0) || !(rotation_sigma >= 0.0))
    throw std::invalid_argument("PoseParticleFilter::diffuse: spreads must be >= 0");
  if (translation_sigma.maxCoeff() > 0.0)
    predict_random_walk_per_axis(translation_, translation_sigma, noise_);
  if (rotation_sigma > 0.0) predict_random_walk(rotation_, rotation_sigma, noise_);
}

void PoseParticleFilter::reweight(const Eigen::Vector3d& position,
                                  const Eigen::Quaterniond& orientation, double covariance_scale) {
  reweight_translation(position, covariance_scale);
  reweight_rotation(orientation, covariance_scale);
}

void PoseParticleFilter::reweight_translation(const Eigen::Vector3d& position,
                                              double covariance_scale) {
  const Eigen::Vector3d& sigma = translation_likelihood_noise_;
  translation_best_exponent_ =
      reweight_gaussian(translation_, position, (covariance_scale * sigma).cwiseProduct(sigma));
  translation_reweighted_ = true;
  // Negated `>=` so that a NaN exponent (a non-finite measurement) counts as underflow too.
  translation_underflow_ =
      translation_underflow_ || !(translation_best_exponent_ >= kLikelihoodUnderflowExponent);
}

void PoseParticleFilter::reweight_rotation(const Eigen::Quaterniond& orientation,
                                           double covariance_scale) {
  const double sigma = rotation_likelihood_noise_;
  rotation_best_exponent_ =
      reweight_gaussian(rotation_, orientation, covariance_scale * sigma * sigma);
  rotation_reweighted_ = true;
  rotation_underflow_ =
      rotation_underflow_ || !(rotation_best_exponent_ >= kLikelihoodUnderflowExponent);
}

Eigen::VectorXd PoseParticleFilter::translation_exponents(const Eigen::Vector3d& position) const {
  Eigen::VectorXd exponents;
  gaussian_exponents(translation_, position, translation_likelihood_noise_.cwiseAbs2(), exponents);
  return exponents;
}

Eigen::VectorXd PoseParticleFilter::rotation_exponents(
    const Eigen::Quaterniond& orientation) const {
  const double sigma = rotation_likelihood_noise_;
  Eigen::VectorXd exponents;
  gaussian_exponents(rotation_, orientation, sigma * sigma, exponents);
  return exponents;
}

void PoseParticleFilter::reweight_translation_by(const Eigen::VectorXd& log_likelihood) {
  translation_.weights.add(log_likelihood);
  translation_reweighted_ = true;
}

void PoseParticleFilter::reweight_rotation_by(const Eigen::VectorXd& log_likelihood) {
  rotation_.weights.add(log_likelihood);
  rotation_reweighted_ = true;
}

bool PoseParticleFilter::update_with_measurement(const Eigen::Vector3d& position,
                                                 const Eigen::Quaterniond& orientation) {
  return reweight_both(position, orientation, 0.0);
}

bool PoseParticleFilter::reweight_both(const Eigen::Vector3d& position,
                                       const Eigen::Quaterniond& orientation,
                                       double min_effective_share) {
  reweight_translation(position);
  update_rotation(orientation, min_effective_share);
  const PortionsReset reset =
      reset_unreached(position, orientation, translation_best_exponent_, rotation_best_exponent_);
  translation_reset_ = reset.translation;
  translation_gaussian_ = false;
  return reset.any();
}

bool PoseParticleFilter::update_with_measurement(const Eigen::Vector3d& position,
                                                 const Eigen::Quaterniond& orientation,
                                                 double min_effective_share) {
  if (!(min_effective_share > 0.0)) return update_with_measurement(position, orientation);
  if (!translation_.weights.uniform())
    return gaussian_where_degenerate(position, orientation, min_effective_share);
  // Equal prior weights (every resampled frame): reweight once, and read the share the
  // likelihood left effective from the posterior weights.
  reweight_translation(position);
  const double best = translation_best_exponent_;
  // The share in single precision, as resampling reads it (1e-7 relative: far finer than any
  // threshold); NaN, and so not under the share, when no weight is usable.
  const double share = effective_share(translation_.weights, translation_kept_);
  if (!takes_gaussian_update(best, share, min_effective_share)) {
    update_rotation(orientation, min_effective_share);
    const PortionsReset reset =
        reset_unreached(position, orientation, best, rotation_best_exponent_);
    translation_reset_ = reset.translation;
    translation_gaussian_ = false;
    return reset.any();
  }
  translation_.weights.reset();  // the prior's moments: its weights were equal
  return take_gaussian_posterior(position, orientation, best, min_effective_share);
}

bool PoseParticleFilter::gaussian_where_degenerate(const Eigen::Vector3d& position,
                                                   const Eigen::Quaterniond& orientation,
                                                   double min_effective_share) {
  const Eigen::VectorXd exponents = translation_exponents(position);
  const double best = exponents.maxCoeff();
  const Eigen::ArrayXd log_weights = exponents.array() + translation_.weights.log().array();
  const Eigen::ArrayXd weights = (log_weights - log_weights.maxCoeff()).exp();
  const double effective = weights.sum() * weights.sum() / weights.square().sum();
  const double share = effective / static_cast<double>(translation_.size());
  if (!takes_gaussian_update(best, share, min_effective_share))
    return reweight_both(position, orientation, min_effective_share);
  return take_gaussian_posterior(position, orientation, best, min_effective_share);
}

bool PoseParticleFilter::take_gaussian_posterior(const Eigen::Vector3d& position,
                                                 const Eigen::Quaterniond& orientation,
                                                 double best_exponent, double min_effective_share) {
  const TranslationMoments prior = translation_moments();
  const Eigen::Matrix3d innovation =
      prior.covariance + translation_likelihood_noise_.cwiseAbs2().asDiagonal().toDenseMatrix();
  const Eigen::Matrix3d gain = innovation.ldlt().solve(prior.covariance).transpose();
  const Eigen::Vector3d mean = prior.mean + gain * (position - prior.mean);
  Eigen::Matrix3d covariance = (Eigen::Matrix3d::Identity() - gain) * prior.covariance;
  covariance = 0.5 * (covariance + covariance.transpose()).eval();
  const Eigen::LLT<Eigen::Matrix3d> root(covariance);
  if (root.info() != Eigen::Success || !mean.allFinite())  // a degenerate cloud: reweight it
    return reweight_both(position, orientation, min_effective_share);
  scatter_around(translation_, Eigen::Vector3d::Zero(), 1.0, noise_);
  translation_.states = (root.matrixL() * translation_.states).colwise() + mean;
  translation_.columns.setZero();
  translation_reweighted_ = translation_underflow_ = false;
  translation_best_exponent_ = best_exponent;

  update_rotation(orientation, min_effective_share);
  const PortionsReset reset = reset_unreached(position, orientation, 0.0, rotation_best_exponent_);
  translation_reset_ = false;
  translation_gaussian_ = true;
  return reset.any();
}

void PoseParticleFilter::update_rotation(const Eigen::Quaterniond& orientation,
                                         double min_effective_share) {
  rotation_gaussian_ = false;
  if (!(min_effective_share > 0.0)) {
    reweight_rotation(orientation);
    return;
  }
  // The share of the posterior weights, prior and likelihood together, as for the translation.
  const bool uniform = rotation_.weights.uniform();
  reweight_rotation(orientation);
  const double share = effective_share(rotation_.weights, rotation_kept_);
  if (!takes_gaussian_update(rotation_best_exponent_, share, min_effective_share)) return;
  // The prior's weights back for its moments (the likelihood taken off again: rare enough that
  // every other frame need not keep a copy).
  if (uniform)
    rotation_.weights.reset();
  else
    rotation_.weights.log() -= rotation_exponents(orientation);
  const RotationMoments moments = rotation_moments();
  const Eigen::Matrix3d covariance = moments.tangent_covariance;
  const Eigen::Matrix3d innovation = covariance + rotation_likelihood_noise_ *
                                                      rotation_likelihood_noise_ *
                                                      Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d gain = innovation.ldlt().solve(covariance).transpose();
  const Eigen::Vector3d step = gain * so3::difference(moments.mean, orientation);
  // The posterior's spread, the same on every tangent axis (as the random walk's).
  const double spread =
      std::sqrt(((Eigen::Matrix3d::Identity() - gain) * covariance).trace() / 3.0);
  if (!step.allFinite() || !(spread >= 0.0) || !std::isfinite(spread)) {
    reweight_rotation(orientation);  // a degenerate cloud: reweight it
    return;
  }
  scatter_around(rotation_, moments.mean * so3::exp(step), spread, noise_);
  rotation_.columns.setZero();
  rotation_reweighted_ = rotation_underflow_ = false;
  rotation_gaussian_ = true;
}

double PoseParticleFilter::effective_share(const LogWeights& weights, KeptRelativeWeights& kept) {
  const std::size_t n = weights.size();
  kept.values.resize(n);
  kept.found = kernels::resampling_weights(weights.log().data(), kept.values.data(), n);
  kept.generation = weights.generation();
  kept.valid = true;
  return kept.found.usable ? kept.found.ess_fraction : std::numeric_limits<double>::quiet_NaN();
}

bool PoseParticleFilter::takes_gaussian_update(double best_exponent, double share,
                                               double min_effective_share) const {
  // Within the reset gate, not an underflow, and under the share (NaN is not under it).
  return !beyond_reset_gate(best_exponent) && best_exponent >= kLikelihoodUnderflowExponent &&
         share < min_effective_share;
}

bool PoseParticleFilter::beyond_reset_gate(double best_exponent) const {
  return options_.reset_gate > 0.0 &&
         best_exponent < -0.5 * options_.reset_gate * options_.reset_gate;
}

PortionsReset PoseParticleFilter::reset_unreached(const Eigen::Vector3d& position,
                                                  const Eigen::Quaterniond& orientation,
                                                  double translation_best_exponent,
                                                  double rotation_best_exponent) {
  PortionsReset reset;
  if (beyond_reset_gate(translation_best_exponent)) {
    scatter_around(translation_, position, options_.observation_noise_translation, noise_);
    translation_.columns.setZero();
    translation_reweighted_ = translation_underflow_ = false;  // the reset replaced the weights
    reset.translation = true;
  }
  if (beyond_reset_gate(rotation_best_exponent)) {
    scatter_around(rotation_, orientation, rotation_likelihood_noise_, noise_);
    rotation_.columns.setZero();
    rotation_reweighted_ = rotation_underflow_ = false;
    reset.rotation = true;
  }
  return reset;
}

ResampleReport PoseParticleFilter::normalise_and_resample() {
  ResampleReport report;
  const bool translation_ok = normalise_and_maybe_resample(
      translation_, translation_reweighted_, options_.resampling, random_, report.ess_translation,
      report.resampled_translation, report.translation_column_means, translation_kept_);
  const bool rotation_ok = normalise_and_maybe_resample(
      rotation_, rotation_reweighted_, options_.resampling, random_, report.ess_rotation,
      report.resampled_rotation, report.rotation_column_means, rotation_kept_);
  translation_kept_.release();
  rotation_kept_.release();
  report.weights_recovered = !translation_ok || !rotation_ok;
  report.likelihood_underflow = translation_underflow_ || rotation_underflow_;
  translation_underflow_ = rotation_underflow_ = false;
  translation_reweighted_ = translation_reweighted_ && !report.resampled_translation;
  rotation_reweighted_ = rotation_reweighted_ && !report.resampled_rotation;
  return report;
}

mrpt::poses::CPose3DPDFGaussian PoseParticleFilter::estimate() const {
  const TranslationMoments t = translation_moments();
  const RotationMoments r = rotation_moments();
  return make_pose_pdf(t.mean, t.covariance, r.mean, r.tangent_covariance);
}

double PoseParticleFilter::translation_log_evidence(const Eigen::Vector3d& position) const {
  Eigen::VectorXd log_terms = translation_exponents(position);
  log_terms += translation_.weights.log();
  const double max_term = log_terms.maxCoeff();
  return max_term + std::log((log_terms.array() - max_term).exp().sum());
}

double PoseParticleFilter::observation_trace(double covariance_scale) const {
  const double t_sigma = options_.observation_noise_translation;
  const double r_sigma = options_.observation_noise_rotation;
  return covariance_scale * 3.0 * (t_sigma * t_sigma + r_sigma * r_sigma);
}

}  // namespace opf
