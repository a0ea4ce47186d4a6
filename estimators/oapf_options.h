#pragma once
// Options of the random-walk occlusion-aware particle filter baseline (Meshgi et al., CVIU 2016),
// adapted to the 6-DoF two-portion particle filter: occlusion chain, likelihoods, search growth.

#include "opf/core/option_schema.h"
#include "opf/particles/particle_filter_options.h"

namespace opf {

struct OcclusionAwarePfOptions {
  /// Particle counts, noises and resampling, the same defaults as the standard PF so the two
  /// baselines differ only in the occlusion model.
  PoseParticleFilterOptions particles;

  /// Rates (1/s) of the continuous-time two-state chain behind every particle's occlusion flag;
  /// a frame of dt seconds switches visible -> occluded with a/(a+b) (1 - exp(-(a+b) dt)) and back
  /// with b/(a+b) (1 - exp(-(a+b) dt)), the exact transition of the chain, so steps of any length
  /// compose (to first order these are 1 - exp(-rate dt)). Meshgi et al. use a per-frame
  /// transition matrix for video; rates carry it over to logs with uneven frame rates. Its
  /// values are not in the project's references, so these come from the OPF paper's scenes.
  /// occlusion_rate = 0.5: an occlusion onset every ~2 s of tracking, the order of the general OP
  /// experiment (three or four occlusions in its 300 frames, ~10 s at the AprilTags' 30 Hz).
  double occlusion_rate = 0.5;
  /// reappearance_rate = 1.0: occlusions last ~1 s on average, between the baseball
  /// experiment's 0.5 s capture outage and the tray passage (frames 250-300, ~1.7 s at 30 Hz).
  /// It also sets how reluctantly occluded particles turn visible while the object stays unseen.
  double reappearance_rate = 1.0;

  /// Probability that the detector misses the object although it is visible: the likelihood of a
  /// missing measurement for a visible particle (occluded particles get 1). 0.1: a dropout of one
  /// frame in ten (blob thresholds, motion blur, tag detections at the image border) is common,
  /// so one missed frame raises the odds of occlusion ten-fold but does not declare it alone.
  /// In (0, 1].
  double miss_probability = 0.1;

  /// Likelihood of a present measurement for an occluded particle (the detection is then a false
  /// one, not of this object), as the Gaussian exponent of a residual of k standard deviations,
  /// exp(-k^2 / 2), on the scale of paper Eq. 5 whose normaliser is dropped. 6: a false detection
  /// spread uniformly over a ~1 m^3 workspace with a 1% false-alarm rate has density
  /// 0.01 / 1 m^3, which against the visible Gaussian's normaliser (2 pi (0.01 m)^2)^(3/2) is
  /// exp(-15.7), i.e. k = 5.6 (rotation: 0.01 / (8 pi^2) against (2 pi (0.05 rad)^2)^(3/2) gives
  /// k = 5.5), rounded up. A tracking cloud never comes near it (P(chi^2_3 > 36) < 1e-7), yet a
  /// detection far from every particle is taken for a false one while the search goes on. > 0.
  double occluded_likelihood_sigmas = 6.0;

  /// Growth (1/s) of an occluded particle's random-walk spread with its time occluded tau:
  /// sigma(tau) = process noise * sqrt(dt) * (1 + growth * tau). Meshgi et al. widen the search
  /// of occluded particles the longer the target stays hidden (no value carries over from image
  /// space); 2: after 1 s hidden a particle steps three times as far per frame, and the cloud's
  /// per-axis spread is sqrt(1 + g + g^2/3) = 2.1 times the standard PF's, ~0.1 m at the default
  /// 0.05 m/sqrt(s): the scale on which objects move while hidden in the paper's scenes (a mug
  /// carries the covered ball 0.4 m). 0 disables the growth (the search then never outruns the
  /// standard PF's). From 0 to 1e3.
  double spread_growth = 2.0;
};

/// The settings file's `oapf:` section (core/option_schema.h). `particles` is not in it: the
/// registry copies `pf:` over it, so both particle baselines run the same filter.
template <class Visitor>
void describe_options(Visitor& v, OcclusionAwarePfOptions& o) {
  v.number("occlusion_rate", o.occlusion_rate, positive("a positive number (1/s)"));
  v.number("reappearance_rate", o.reappearance_rate, positive("a positive number (1/s)"));
  v.number("miss_probability", o.miss_probability, unit_fraction());
  v.number("occluded_likelihood_sigmas", o.occluded_likelihood_sigmas, positive());
  // At g = 1e3 the spread after 1 s hidden is 578 times the PF's. From 1e5 on, with the noise
  // settings at their limit (kMaxNoise), the rotation kernels' floats overflow within 2 s.
  v.number("spread_growth", o.spread_growth, between(0.0, 1e3, "a number (1/s) from 0 to 1e3"));
}

}  // namespace opf
