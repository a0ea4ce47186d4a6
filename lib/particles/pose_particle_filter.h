#pragma once
// The 6-DoF pose particle filter of paper Sec. III-A, as composable steps (predict, reweight,
// normalise and resample, moments): a translation portion and a rotation portion, each with its
// own particles and weights, one seeded generator. Estimators (standard PF, OPF, occlusion-aware
// PF) drive the steps; one with a per-particle state of its own keeps it in the portions' columns
// (particle_portion.h) and its own likelihood in reweight_*_by().

#include "opf/core/random.h"
#include "opf/particles/gaussian_sampler.h"
#include "opf/particles/particle_filter_options.h"
#include "opf/particles/particle_portion.h"
#include "opf/particles/particle_statistics.h"

#include <mrpt/poses/CPose3DPDFGaussian.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace opf {

/// What the last normalise-and-resample step saw and did, per portion (MRPT's
/// TParticleFilterStats, extended).
struct ResampleReport {
  double ess_translation = 1.0;  ///< ESS/N before resampling
  double ess_rotation = 1.0;
  bool resampled_translation = false;
  bool resampled_rotation = false;
  /// True when every weight of a portion vanished (a measurement far from every particle) and
  /// the weights were reset to uniform instead of becoming NaN.
  bool weights_recovered = false;
  /// True when a reweight since the last step found the likelihood of every particle of a portion
  /// below the smallest normal double (kLikelihoodUnderflowExponent); log-domain normalisation
  /// kept the weights' ratios. Not set for a portion that sensor resetting then re-scattered.
  bool likelihood_underflow = false;

  /// Per portion with columns (particle_portion.h), each column's weighted mean under the
  /// normalised weights, taken before resampling: an estimator's per-particle state summarised
  /// without the resampling draw's noise. Empty for a portion without columns.
  Eigen::VectorXd translation_column_means;
  Eigen::VectorXd rotation_column_means;

  /// Either way the weights of a portion had to be rescued from underflow.
  bool weights_underflow() const { return weights_recovered || likelihood_underflow; }
};

/// Which portions sensor resetting re-scattered.
struct PortionsReset {
  bool translation = false;
  bool rotation = false;
  bool any() const { return translation || rotation; }
};

/// exp(x) is below the smallest normal double for x under log(DBL_MIN) = -708.4: a Gaussian
/// exponent this low means the measurement lies about 37.6 (inflated) sigmas from the particle.
inline constexpr double kLikelihoodUnderflowExponent = -708.3964185322641;

/// A portion's single-precision relative weights as the share test read them
/// (kernels::resampling_weights), kept for the systematic resampling that follows in the same
/// step: the exponentials taken once instead of twice. They hold while the log-weights are at
/// the generation they were read from (LogWeights::generation).
struct KeptRelativeWeights {
  std::vector<float> values;
  kernels::NormalisedWeights found;
  std::uint64_t generation = 0;
  bool valid = false;

  /// Whether they are still those of `weights`.
  bool hold_for(const LogWeights& weights) const {
    return valid && generation == weights.generation();
  }
  /// Gives the storage back (nothing is kept between steps).
  void release() {
    std::vector<float>().swap(values);
    valid = false;
  }
};

class PoseParticleFilter {
 public:
  /// Throws std::invalid_argument naming the option when an option is out of range.
  PoseParticleFilter(const PoseParticleFilterOptions& options, std::uint64_t seed);

  /// Scatters the particles around the first measurement with the observation noise.
  void initialise(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation);

  /// Random-walk prediction over `dt` seconds (per-step sigma = density * sqrt(dt)).
  void predict(double dt);
  void predict_translation(double dt);
  void predict_rotation(double dt);
  /// The rotation's observation noise (rad) in the likelihood and a sensor reset's scatter from
  /// now on: the OPF's estimate of the detector's own. observation_trace() keeps the configured
  /// value (the uncertainty module's Q and the alert are the sensor's declared noise). Throws
  /// std::invalid_argument unless it is positive and finite.
  void set_rotation_likelihood_noise(double sigma);
  /// The translation's observation noise per world axis (m), in the likelihood and the Gaussian
  /// posterior from now on (a detector's depth is often far noisier than its image-plane
  /// position). The reset gate counts in these sigmas, as the rotation's does in its own; a reset
  /// scatters with the configured value. Throws std::invalid_argument unless each is positive and
  /// finite.
  void set_translation_likelihood_noise(const Eigen::Vector3d& sigma);
  /// The same on every axis for one detection: the configured observation noise with the
  /// detection's stated extra noise (m, Detection::extra_noise) added in variance
  /// (observation_sigma); 0 puts the configured value back.
  void set_translation_extra_noise(double extra_noise);

  /// A random walk with a spread of its own per particle (m, rad): an estimator whose particles
  /// move differently by their own state (the occlusion-aware PF's widening search).
  void predict_per_particle(const Eigen::VectorXd& translation_sigmas,
                            const Eigen::VectorXd& rotation_sigmas);

  /// shift(translation, rotation), then predict(dt), in one pass over the particles, with the
  /// translation's spread per world axis at least sqrt(variance(d)) (m) and the rotation's per
  /// tangent axis at least sqrt(rotation_variance) (rad): a motion model whose step is less
  /// certain than the random walk spreads the particles as it does.
  void predict(double dt, const Eigen::Vector3d& translation, const Eigen::Quaterniond& rotation,
               const Eigen::Vector3d& variance, double rotation_variance);

  /// Moves every particle rigidly: translation particles by `translation`, rotation particles by
  /// the world-frame rotation `rotation` (q <- rotation * q). The motion model f of paper Eq. 3
  /// when the object is carried by a known motion.
  void shift(const Eigen::Vector3d& translation, const Eigen::Quaterniond& rotation);

  /// Moves every particle with a carrier that went from `from` to `to` turning by the world-frame
  /// `rotation`: positions p <- to + rotation (p - from), orientations q <- rotation * q. A body
  /// carried at an offset turns about its carrier, not about itself.
  void carry(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
             const Eigen::Quaterniond& rotation);

  /// Adds zero-mean Gaussian noise: per world axis `translation_sigma` (m) to the translation
  /// particles, `rotation_sigma` (rad, per body axis) to the rotation particles. Weights are kept.
  void diffuse(const Eigen::Vector3d& translation_sigma, double rotation_sigma);

  /// Weights the particles by the likelihood of a (real or virtual) measurement with observation
  /// covariance covariance_scale * Q (the OPF's Q~ = alpha Q, paper Eq. 14).
  void reweight(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                double covariance_scale = 1.0);
  void reweight_translation(const Eigen::Vector3d& position, double covariance_scale = 1.0);
  void reweight_rotation(const Eigen::Quaterniond& orientation, double covariance_scale = 1.0);

  /// The exponents of Eq. 5 (Q unscaled) per particle, without reweighting: for an estimator
  /// whose likelihood is built on them (reweight_*_by).
  Eigen::VectorXd translation_exponents(const Eigen::Vector3d& position) const;
  Eigen::VectorXd rotation_exponents(const Eigen::Quaterniond& orientation) const;
  /// Multiplies a portion's weights by likelihoods an estimator computed itself, in the log
  /// domain (one per particle).
  void reweight_translation_by(const Eigen::VectorXd& log_likelihood);
  void reweight_rotation_by(const Eigen::VectorXd& log_likelihood);

  /// The update with a REAL measurement (Q unscaled): reweight, or, for a portion with no
  /// particle within options().reset_gate sigmas of it, scatter that portion around it (sensor
  /// resetting). Returns whether any portion was reset.
  bool update_with_measurement(const Eigen::Vector3d& position,
                               const Eigen::Quaterniond& orientation);
  /// The same, except where the translation likelihood would leave fewer than
  /// `min_effective_share` of the translation particles effective (a measurement in the cloud's
  /// far tail, whose weights would collapse onto the few particles nearest it and report their
  /// tiny spread). That portion then takes the Gaussian posterior of its own mean and covariance
  /// and the measurement (a Kalman update with the observation noise) and is drawn anew from it
  /// with uniform weights. A measurement beyond reset_gate is reset as before.
  bool update_with_measurement(const Eigen::Vector3d& position,
                               const Eigen::Quaterniond& orientation, double min_effective_share);
  /// Whether the last update_with_measurement took the translation's Gaussian posterior.
  bool translation_took_gaussian_posterior() const { return translation_gaussian_; }
  /// Whether the last update_with_measurement with a share took the rotation's: the same test on
  /// the rotation portion, whose Gaussian posterior is a Kalman update in the tangent space at
  /// the particles' mean, drawn anew with the same spread on every axis.
  bool rotation_took_gaussian_posterior() const { return rotation_gaussian_; }
  /// Sensor resetting alone, given the best exponent of each portion (-d^2/2 for the particle
  /// nearest the measurement, in sigmas): a portion whose best is below -reset_gate^2/2 is
  /// scattered around the measurement with uniform weights and its columns at 0.
  PortionsReset reset_unreached(const Eigen::Vector3d& position,
                                const Eigen::Quaterniond& orientation,
                                double translation_best_exponent, double rotation_best_exponent);
  /// Whether the last update_with_measurement reset the translation portion (the object was
  /// somewhere the cloud did not reach), as opposed to only the rotation portion.
  bool translation_was_reset() const { return translation_reset_; }

  /// Normalises each portion and resamples it per the options. A portion whose weights were not
  /// changed since its last resampling is left alone (uniform weights gain nothing from it).
  ResampleReport normalise_and_resample();

  TranslationMoments translation_moments() const { return opf::translation_moments(translation_); }
  RotationMoments rotation_moments() const { return opf::rotation_moments(rotation_); }
  /// The weighted mean pose and its covariance, MRPT's Gaussian pose.
  mrpt::poses::CPose3DPDFGaussian estimate() const;
  /// log p(z | particles) = log sum_i w_i N(z; x_i, Q) of a position measurement under the
  /// translation portion (up to a constant shared by every filter with the same Q): how well this
  /// filter explains z, used to pick the surviving hypothesis when an object reappears.
  double translation_log_evidence(const Eigen::Vector3d& position) const;

  /// Restarts the generators (a copied filter must not replay its original's random draws).
  void reseed(std::uint64_t seed);
  /// The generator of resampling draws, for an estimator's own draws (occlusion flags): one
  /// seeded stream per filter.
  Random& random() { return random_; }

  /// trace(covariance_scale * Q) for the 6-DoF observation covariance Q (paper Eq. 15).
  double observation_trace(double covariance_scale = 1.0) const;

  const PoseParticleFilterOptions& options() const { return options_; }
  /// Read-write: an estimator adds its columns and moves its particles through these.
  TranslationParticles& translation() { return translation_; }
  const TranslationParticles& translation() const { return translation_; }
  RotationParticles& rotation() { return rotation_; }
  const RotationParticles& rotation() const { return rotation_; }

 private:
  /// Whether a portion's best exponent (-d^2/2, in sigmas) puts the measurement beyond
  /// options().reset_gate of every particle (never with the gate at 0).
  bool beyond_reset_gate(double best_exponent) const;
  /// Whether a measurement whose likelihood leaves `share` (0-1) of a portion's particles
  /// effective takes the Gaussian posterior: within the reset gate, not underflowing everywhere,
  /// and under min_effective_share.
  bool takes_gaussian_update(double best_exponent, double share, double min_effective_share) const;
  /// update_with_measurement's share test on weights that are not all equal: the likelihood's
  /// exponents and the prior's weights together, before anything is changed.
  bool gaussian_where_degenerate(const Eigen::Vector3d& position,
                                 const Eigen::Quaterniond& orientation, double min_effective_share);
  /// The translation portion redrawn from the Gaussian posterior of its moments and the
  /// measurement; the rotation by update_rotation.
  bool take_gaussian_posterior(const Eigen::Vector3d& position,
                               const Eigen::Quaterniond& orientation, double best_exponent,
                               double min_effective_share);
  /// Both portions reweighted (the rotation by update_rotation), then sensor resetting.
  bool reweight_both(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                     double min_effective_share);
  /// The rotation reweighted, or, where that leaves under min_effective_share of its particles
  /// effective (within the gate, no underflow; never with a share of 0), redrawn from the
  /// Gaussian posterior of its prior moments and the measurement.
  void update_rotation(const Eigen::Quaterniond& orientation, double min_effective_share);
  /// The share of effective particles the weights leave, NaN when none is usable; their relative
  /// weights kept in `kept`.
  static double effective_share(const LogWeights& weights, KeptRelativeWeights& kept);

  PoseParticleFilterOptions options_;
  /// m per axis: options_' value on every axis unless set_translation_likelihood_noise
  Eigen::Vector3d translation_likelihood_noise_;
  double rotation_likelihood_noise_;  ///< rad: options_' value unless set_rotation_likelihood_noise
  Random random_;                     ///< resampling draws
  GaussianSampler noise_;             ///< process and initialisation noise, in bulk
  TranslationParticles translation_;
  RotationParticles rotation_;
  bool translation_reweighted_ = false;
  bool rotation_reweighted_ = false;
  bool translation_gaussian_ = false;
  bool rotation_gaussian_ = false;
  double translation_best_exponent_ = 0.0;  ///< of the last reweight, for sensor resetting
  double rotation_best_exponent_ = 0.0;
  bool translation_reset_ = false;      ///< by the last update_with_measurement
  bool translation_underflow_ = false;  ///< since the last normalise_and_resample
  bool rotation_underflow_ = false;
  KeptRelativeWeights translation_kept_, rotation_kept_;  ///< from the share tests, this step
};

/// Throws std::invalid_argument naming the first option that is out of range.
void validate(const PoseParticleFilterOptions& options);

}  // namespace opf
