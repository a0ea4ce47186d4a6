#pragma once
// Options of the Object Permanence Filter (paper Sec. III): the particle filter it extends and
// the four modules of its Object Permanence update, each switchable off for ablations.

#include "fit/trajectory_fit.h"
#include "particles/particle_filter_options.h"
#include "permanence/covariance_inflation.h"
#include "permanence/motion_classifier.h"
#include "permanence/occluder_selection.h"
#include "permanence/safety_feedback.h"

#include <cstddef>

namespace opf {

struct OpfModules {
  bool dynamics = true;     ///< extrapolate a moving object's fitted trajectory (Sec. III-B.1)
  bool occluder = true;     ///< follow the occluder of a static object (Sec. III-B.2)
  bool uncertainty = true;  ///< inflate Q while hidden (Sec. III-B.3); off: Q~ = Q
};

struct OpfOptions {
  PoseParticleFilterOptions particles;
  OpfModules modules;
  /// H, the states the dynamics module looks back on (paper: 50). The history holds estimates
  /// from frames with a real measurement.
  std::size_t history_length = 50;
  /// After an occlusion longer than this (s) in which the object was carried by its occluder or
  /// only predicted, the history restarts when it reappears: the states before it describe where
  /// the object was, not how it moves now (the ball revealed at a new place must not read as
  /// "moving" along the jump). It also restarts when a measurement resets the filter.
  double history_reset_gap = 0.5;
  /// While hidden, move the particles with the carrier of the virtual measurement (the fitted
  /// trajectory, or the occluder's filtered estimate) as the motion model f of Eq. 3. The paper
  /// only feeds the virtual measurement to the update; with a random-walk prior the estimate then
  /// lags a moving virtual measurement by about v (1 - K) / K per frame, and the lag grows as Q~
  /// inflates and the gain K falls. false gives the paper-literal filter (an ablation).
  bool carry_particles = true;
  MotionThresholds motion;
  TrajectoryFitOptions trajectory;
  OccluderOptions occluder;
  UncertaintyOptions uncertainty;
  FeedbackOptions feedback;
};

/// Throws std::invalid_argument naming the first option out of range.
void validate(const OpfOptions& options);

}  // namespace opf
