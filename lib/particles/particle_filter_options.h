#pragma once
// Options of the 6-DoF pose particle filter (paper Sec. III-A): two particle portions, one for
// translation and one for rotation, a random-walk motion model with Gaussian noise R and the
// Gaussian likelihood of Eq. 5 with observation covariance Q.

#include "opf/core/enum_names.h"
#include "opf/core/option_schema.h"

#include <mrpt/bayes/CParticleFilter.h>

#include <cstddef>

namespace opf {

using ResamplingScheme = mrpt::bayes::CParticleFilter::TParticleResamplingAlgorithm;

/// MRPT's four schemes as settings files spell them.
inline constexpr EnumNames<ResamplingScheme, 4> kResamplingSchemeNames = {{
    {mrpt::bayes::CParticleFilter::prMultinomial, "multinomial"},
    {mrpt::bayes::CParticleFilter::prResidual, "residual"},
    {mrpt::bayes::CParticleFilter::prStratified, "stratified"},
    {mrpt::bayes::CParticleFilter::prSystematic, "systematic"},
}};

struct ResamplingOptions {
  /// Systematic by default: lowest variance of the four for the same cost.
  ResamplingScheme scheme = mrpt::bayes::CParticleFilter::prSystematic;
  /// The paper resamples after every update (Eq. 6). When false, resample only when the normalised
  /// effective sample size ESS/N falls below `ess_threshold` (MRPT's BETA).
  bool every_frame = true;
  double ess_threshold = 0.5;
};

/// The most particles a portion may hold: the resampler marks each particle's end slot in 32 bits.
inline constexpr std::size_t kMaxParticlesPerPortion = (std::size_t{1} << 31) - 1;

struct PoseParticleFilterOptions {
  /// Particles per portion; the paper uses 5000 + 5000 per object (Sec. IV-B).
  std::size_t translation_particles = 5000;
  std::size_t rotation_particles = 5000;
  /// Process noise R as random-walk densities: the per-step standard deviation is
  /// sigma * sqrt(dt), so logs with uneven rates diffuse consistently. Units m/sqrt(s),
  /// rad/sqrt(s).
  double process_noise_translation = 0.05;
  double process_noise_rotation = 0.1;
  /// Observation noise Q (Eq. 5): standard deviation per axis, m and rad (rotation in the tangent
  /// space of the measured orientation). Also the spread of the particles at initialisation.
  double observation_noise_translation = 0.01;
  double observation_noise_rotation = 0.05;
  ResamplingOptions resampling;
  /// Sensor resetting (Lenser & Veloso, ICRA 2000): when no particle of a portion lies within
  /// reset_gate observation sigmas of a real measurement, the object was moved while unseen (or
  /// the filter lost it), and the portion is scattered around the measurement instead of crawling
  /// there by random walk over many frames. 0 disables it.
  double reset_gate = 5.0;
};

/// The settings file's `pf:` section (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, ResamplingOptions& o) {
  v.choice("scheme", kResamplingSchemeNames, o.scheme);
  v.flag("every_frame", o.every_frame);
  v.number("ess_threshold", o.ess_threshold, unit_fraction());
}

template <class Visitor>
void describe_options(Visitor& v, PoseParticleFilterOptions& o) {
  constexpr Bounds count =
      between(1, static_cast<double>(kMaxParticlesPerPortion), "a positive integer below 2^31");
  v.integer("translation_particles", o.translation_particles, count);
  v.integer("rotation_particles", o.rotation_particles, count);
  v.section("process_noise", [&] {
    v.number("translation", o.process_noise_translation,
             noise_scale("a positive number (m/sqrt(s)) up to 1e6"));
    v.number("rotation", o.process_noise_rotation,
             noise_scale("a positive number (rad/sqrt(s)) up to 1e6"));
  });
  describe_observation_noise(v, o.observation_noise_translation, o.observation_noise_rotation);
  v.section("resampling", [&] { describe_options(v, o.resampling); });
  v.number("reset_gate", o.reset_gate, non_negative("a number of sigmas >= 0 (0 disables)"));
}

}  // namespace opf
