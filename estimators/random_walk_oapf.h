#pragma once
// The random-walk occlusion-aware particle filter baseline (Meshgi et al., CVIU 2016): particles
// carry an occlusion flag and, while occluded, random-walk in a widening search; no object
// permanence reasoning.

#include "opf/core/estimator.h"
#include "opf/core/random.h"
#include "opf/estimators/oapf_options.h"
#include "opf/particles/particle_portion.h"
#include "opf/particles/pose_particle_filter.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace opf {

/// Runs on the pose particle filter (particles/pose_particle_filter.h) with three columns per
/// portion, which resampling moves with the states: the occlusion flag, the time occluded and the
/// flag's posterior probability.
///
/// Model per portion (translation, rotation), per particle i with flag o_i and time occluded tau_i:
///  - motion: a random walk of spread process noise * sqrt(dt), times (1 + growth * tau_i) while
///    the particle is occluded;
///  - flag: the two-state chain of the options' rates;
///  - likelihood: measurement present, Eq. 5's Gaussian if visible and the constant
///    exp(-k^2 / 2) if occluded; measurement missing, miss_probability if visible and 1 if
///    occluded.
/// The flag is drawn from its posterior given the chain and the particle's two likelihoods, and the
/// weight multiplied by their chain-weighted sum (the optimal proposal for the discrete state,
/// Doucet, Gordon and Krishnamurthy, IEEE TSP 2001). Same model as drawing the flag from the chain
/// first, but an occluded particle that lands on a reappearing object can take it up at once:
/// drawn blindly, only the few particles the chain happens to flip would see the measurement, too
/// few to find an object that reappears away from where it vanished (0.3 m away after 1 s, the
/// blind draw lost the object for more than 10 frames in half the runs, where this takes 2).
class OcclusionAwareParticleFilter final : public Estimator {
 public:
  /// Throws std::invalid_argument naming the first option out of range.
  OcclusionAwareParticleFilter(const OcclusionAwarePfOptions& options, std::uint64_t seed);

  std::string_view name() const override { return "oapf"; }
  Estimate initialise(double t, const mrpt::poses::CPose3D& first_measurement) override;
  /// A missing measurement gives mode kRandomWalk, a present one kMeasured.
  Estimate step(double t, const mrpt::poses::CPose3D* measurement,
                const EnsembleView& ensemble) override;

  /// The portions' columns.
  enum Column : Eigen::Index {
    kOccluded = 0,           ///< 1 = occluded, 0 = visible
    kTimeOccluded = 1,       ///< s; 0 for a visible particle
    kOccludedPosterior = 2,  ///< the flag's posterior probability of occlusion at the last step
    kColumns = 3
  };

  const OcclusionAwarePfOptions& options() const { return options_; }
  const TranslationParticles& translation() const { return filter_.translation(); }
  const RotationParticles& rotation() const { return filter_.rotation(); }
  /// Weighted fraction of occluded particles after the last step, per portion: the weights times
  /// each particle's posterior probability of occlusion rather than its drawn flag, which has the
  /// same expectation without the draw's noise.
  double translation_occlusion_probability() const { return translation_occlusion_; }
  double rotation_occlusion_probability() const { return rotation_occlusion_; }
  /// Statistics of the last step's normalisation and resampling.
  const ResampleReport& last_report() const { return last_report_; }

 private:
  Estimate make_estimate(double t, EstimateMode mode, RecoveryEvents recovery = {}) const;

  OcclusionAwarePfOptions options_;
  PoseParticleFilter filter_;  ///< its generator also draws the flags
  double translation_occlusion_ = 0.0;
  double rotation_occlusion_ = 0.0;
  ResampleReport last_report_;
  double last_t_ = 0.0;
  bool initialised_ = false;
};

/// Throws std::invalid_argument naming the first option out of range.
void validate(const OcclusionAwarePfOptions& options);

}  // namespace opf
