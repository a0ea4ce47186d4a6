#pragma once
// Options of the Object Permanence Filter (paper Sec. III): the particle filter it extends and
// the four modules of its Object Permanence update, each switchable off for ablations.

#include "opf/core/enum_names.h"
#include "opf/core/option_schema.h"
#include "opf/fit/trajectory_fit.h"
#include "opf/particles/particle_filter_options.h"
#include "opf/permanence/covariance_inflation.h"
#include "opf/permanence/motion_classifier.h"
#include "opf/permanence/motion_prediction.h"
#include "opf/permanence/occluder_selection.h"
#include "opf/permanence/safety_feedback.h"

#include <cstddef>

namespace opf {

struct OpfModules {
  bool dynamics = true;     ///< extrapolate a moving object's fitted trajectory (Sec. III-B.1)
  bool occluder = true;     ///< follow the occluder of a static object (Sec. III-B.2)
  bool uncertainty = true;  ///< inflate Q while hidden (Sec. III-B.3); off: Q~ = Q
};

/// How the dynamics module extrapolates a moving hidden object.
enum class DynamicsPredictor {
  /// The model chosen from the object's own history (permanence/motion_prediction.h): continuous
  /// with the last estimate, with a prediction covariance that spreads the particles and sets
  /// Q~. The toolkit's default.
  kSelected,
  /// The paper's rule (Eq. 12): the Ceres polynomial fit of `trajectory` to the last H estimates,
  /// fed as a virtual measurement with Q~ inflated by the uncertainty module.
  kPaper,
};
inline constexpr EnumNames<DynamicsPredictor, 2> kDynamicsPredictorNames = {
    {{DynamicsPredictor::kSelected, "selected"}, {DynamicsPredictor::kPaper, "paper"}}};

struct DynamicsOptions {
  DynamicsPredictor predictor = DynamicsPredictor::kSelected;
  MotionPredictionOptions selection;  ///< of the kSelected predictor
};

struct OpfOptions {
  PoseParticleFilterOptions particles;
  OpfModules modules;
  /// H, the states the `paper` predictor looks back on (paper: 50). The history holds estimates
  /// from frames with a real measurement; the `selected` predictor keeps
  /// dynamics.selection.history_window seconds of them instead.
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
  /// While the object is visible, move the particles by the velocity and angular velocity of
  /// its last `velocity_window` seconds of measurements before the random walk, so a fast object
  /// is followed without lag. false: the paper's pure random walk.
  bool velocity_drift = true;
  double velocity_window = 0.3;  ///< s
  /// While the object is visible, its rotation's observation noise is the detector's own jitter
  /// (permanence/detector_jitter.h) over the last history_window seconds, between a tenth of the
  /// configured observation_noise.rotation and that value: a likelihood wider than the detector's
  /// noise trails every turn by a share of it. false: the configured value, always (the paper's).
  bool adaptive_rotation_noise = true;
  /// The same for translation, per world axis (a depth read from an object's size jitters far
  /// more than its image-plane position): between a tenth of observation_noise.translation and
  /// that value. false: the configured value on every axis (the paper's).
  bool adaptive_translation_noise = false;
  /// At the onset of a predicted motion (the selected predictor), narrow the translation
  /// particles about their mean, per axis, to uncertainty_scale times what the history shows of
  /// the estimate's error (its RMS distance from the measurements, with the detector's noise
  /// added), where the cloud is wider: the cloud's spread while visible is the configured
  /// observation noise's (1 cm), which can be twenty times the detector's, and the reported spread
  /// while hidden would then say nothing of how far off the estimate may be. false: the cloud as
  /// the filter left it.
  bool measured_onset_spread = true;
  /// With measured_onset_spread, also widen the cloud to that spread where it is narrower, on an
  /// axis whose detector noise (read from the measurements) exceeds the configured observation
  /// noise: the cloud is then the posterior under a noise finer than the detector's (a walker's
  /// depth read from her size jitters by centimetres), narrower than how far the next detection
  /// may lie from the estimate, and a hidden object is checked against that detection when it
  /// reappears. false: never widens.
  bool widen_onset_spread = true;
  /// At the first measurement after a gap, where the translation likelihood would leave fewer
  /// than this share of the particles effective (the object turns up in the far tail of the
  /// cloud the gap left), the translation takes the Gaussian posterior of the cloud's moments and
  /// the measurement instead (PoseParticleFilter::update_with_measurement): reweighted, the cloud
  /// would collapse onto the few particles nearest the measurement and report their tiny spread
  /// several centimetres off. 0: always reweight (the paper's).
  double reacquisition_gaussian_share = 0.01;
  /// s hidden after which the dynamics module's prediction stops moving the object and holds it,
  /// its uncertainty still growing (a bounded hidden state: no extrapolation runs off for ever;
  /// the bundled scenes extrapolate correctly for up to 3 s, under the sugar-dropping hand). The
  /// prediction also holds once its spread reaches the uncertainty module's cap.
  double hold_after = 4.0;
  DynamicsOptions dynamics;
  MotionThresholds motion;
  TrajectoryFitOptions trajectory;
  OccluderOptions occluder;
  UncertaintyOptions uncertainty;
  FeedbackOptions feedback;
};

/// The settings file's `opf:` section (core/option_schema.h). `particles` is not in it: the
/// registry copies `pf:` over it, so the OPF and the standard PF run the same filter.
template <class Visitor>
void describe_options(Visitor& v, OpfOptions& o) {
  v.section("modules", [&] {
    v.flag("dynamics", o.modules.dynamics);
    v.flag("occluder", o.modules.occluder);
    v.flag("uncertainty", o.modules.uncertainty);
  });
  v.integer("history_length", o.history_length, at_least(2, "an integer H >= 2"));
  v.number("history_reset_gap", o.history_reset_gap, non_negative("a number of seconds >= 0"));
  v.flag("carry_particles", o.carry_particles);
  v.flag("velocity_drift", o.velocity_drift);
  v.flag("adaptive_rotation_noise", o.adaptive_rotation_noise);
  v.flag("adaptive_translation_noise", o.adaptive_translation_noise);
  v.flag("measured_onset_spread", o.measured_onset_spread);
  v.flag("widen_onset_spread", o.widen_onset_spread);
  v.number("reacquisition_gaussian_share", o.reacquisition_gaussian_share,
           between(0.0, 1.0, "a share from 0 to 1"));
  v.number("velocity_window", o.velocity_window, positive("a positive number of s"));
  v.number("hold_after", o.hold_after, positive("a positive number of s"));
  v.section("dynamics", [&] {
    v.choice("predictor", kDynamicsPredictorNames, o.dynamics.predictor);
    describe_options(v, o.dynamics.selection);
  });
  v.section("motion_thresholds", [&] { describe_options(v, o.motion); });
  v.section("trajectory", [&] { describe_options(v, o.trajectory); });
  v.section("occluder", [&] { describe_options(v, o.occluder); });
  v.section("uncertainty", [&] { describe_options(v, o.uncertainty); });
  v.section("feedback", [&] { describe_options(v, o.feedback); });
}

/// Throws std::invalid_argument naming the first option out of range ("OPF option
/// uncertainty.kappa must be ..."), or a line-of-sight plane without a camera.
void validate(const OpfOptions& options);

}  // namespace opf
