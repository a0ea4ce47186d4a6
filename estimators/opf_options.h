#pragma once
// Options of the Object Permanence Filter (paper Sec. III): the particle filter it extends and
// the four modules of its Object Permanence update, each switchable off for ablations.

#include "opf/core/enum_names.h"
#include "opf/core/option_schema.h"
#include "opf/fit/trajectory_fit.h"
#include "opf/motion/axis_motion_model.h"
#include "opf/motion/rotation_model.h"
#include "opf/particles/particle_filter_options.h"
#include "opf/permanence/covariance_inflation.h"
#include "opf/permanence/motion_classifier.h"
#include "opf/permanence/motion_model_bank_options.h"
#include "opf/permanence/occluder_selection.h"
#include "opf/permanence/rotation_model_bank_options.h"
#include "opf/permanence/safety_feedback.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace opf {

struct OpfModules {
  bool dynamics = true;     ///< extrapolate a moving object's fitted trajectory (Sec. III-B.1)
  bool occluder = true;     ///< follow the occluder of a static object (Sec. III-B.2)
  bool uncertainty = true;  ///< inflate Q while hidden (Sec. III-B.3); off: Q~ = Q
};

/// How the dynamics module extrapolates a hidden object.
enum class DynamicsPredictor {
  /// The motion-model banks (permanence/motion_model_bank.h, rotation_model_bank.h) run over the
  /// object's measurements; while it is hidden its particles follow their predictive mixture
  /// (permanence/mixture_particle_motion.h). The toolkit's default.
  kBank,
  /// The paper's rule (Eq. 12): the Ceres polynomial fit of `trajectory` to the last H estimates,
  /// fed as a virtual measurement with Q~ inflated by the uncertainty module.
  kPaper,
};
inline constexpr EnumNames<DynamicsPredictor, 2> kDynamicsPredictorNames = {
    {{DynamicsPredictor::kBank, "bank"}, {DynamicsPredictor::kPaper, "paper"}}};

/// The translation models' names in `dynamics.models`.
inline constexpr EnumNames<MotionModel, 4> kBankModelNames = {
    {{MotionModel::kConstantPosition, "position"},
     {MotionModel::kConstantVelocity, "velocity"},
     {MotionModel::kDampedVelocity, "damped"},
     {MotionModel::kBallistic, "ballistic"}}};
/// The rotation models' names in `dynamics.rotation_models`.
inline constexpr EnumNames<RotationModel, 3> kRotationBankModelNames = {
    {{RotationModel::kConstantOrientation, "orientation"},
     {RotationModel::kConstantAngularVelocity, "angular_velocity"},
     {RotationModel::kDampedAngularVelocity, "damped_angular_velocity"}}};

struct DynamicsOptions {
  DynamicsPredictor predictor = DynamicsPredictor::kBank;
  /// The bank's translation models (each at its stated intensity grid); drop one to ablate it.
  std::vector<MotionModel> models = {MotionModel::kConstantPosition, MotionModel::kConstantVelocity,
                                     MotionModel::kDampedVelocity, MotionModel::kBallistic};
  std::vector<RotationModel> rotation_models = {RotationModel::kConstantOrientation,
                                                RotationModel::kConstantAngularVelocity,
                                                RotationModel::kDampedAngularVelocity};
  /// T_memory (s) of the models' weights (permanence/model_weights.h).
  double memory = 1.0;
  /// The world's up (gravity is -9.81 up m/s^2): the ballistic model, and the occluder module's
  /// height above an object.
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
};

/// The banks' options from the OPF's (the observation noise is the particle filter's Q).
MotionModelBankOptions translation_bank_options(const DynamicsOptions& dynamics,
                                                double observation_noise);
RotationModelBankOptions rotation_bank_options(const DynamicsOptions& dynamics,
                                               double observation_noise);

struct OpfOptions {
  PoseParticleFilterOptions particles;
  OpfModules modules;
  /// H, the states the motion test and the `paper` predictor look back on (paper: 50): estimates
  /// from frames with a real measurement.
  std::size_t history_length = 50;
  /// After an occlusion longer than this (s; a constant, not a setting) in which the object was
  /// carried by its occluder or held, the history restarts when it reappears: the states before it
  /// describe where the object was, not how it moves now (the ball revealed at a new place must
  /// not read as "moving" along the jump). It also restarts when a measurement resets the filter.
  double history_reset_gap = 0.5;
  /// While hidden, move the particles with the carrier of the virtual measurement (the fitted
  /// trajectory, or the occluder's filtered estimate) as the motion model f of Eq. 3. The paper
  /// only feeds the virtual measurement to the update; with a random-walk prior the estimate then
  /// lags a moving virtual measurement by about v (1 - K) / K per frame, and the lag grows as Q~
  /// inflates and the gain K falls. false gives the paper-literal filter (an ablation).
  bool carry_particles = true;
  /// While the object is visible, move the particles by the banks' velocity and angular velocity
  /// (their mixtures' means) before the random walk: the proposal of a particle filter whose
  /// motion model is the bank's, so a fast object is followed without lag. false: the paper's
  /// pure random walk.
  bool velocity_drift = true;
  /// The observation noise is the detector's own, as it states and shows it (false: Q of paper
  /// Eq. 5 as configured, always: the paper's):
  /// - a detection's stated extra noise (Detection::extra_noise: a partial view's, the log's
  ///   `extra_noise` column) adds in variance to the translation's, in the likelihood and the
  ///   banks (observation_sigma), and a carrier's partial view is read as one;
  /// - while the object is visible, its rotation's is the detector's own jitter
  ///   (permanence/detector_jitter.h) over the last 2 s of measurements, between a tenth of the
  ///   configured observation_noise.rotation and that value: a likelihood wider than the
  ///   detector's noise trails every turn by a share of it.
  bool detector_noise = true;
  /// Where a measurement's translation likelihood would leave fewer than this share of the
  /// particles effective (it falls in the far tail of the cloud: the first one after a gap, or one
  /// of a slow log whose step the banks could not predict to within the detector's noise), the
  /// translation takes the Gaussian posterior of the cloud's moments and the measurement instead
  /// (PoseParticleFilter::update_with_measurement): reweighted, the cloud would collapse onto the
  /// few particles nearest the measurement and report their tiny spread centimetres off. The
  /// rotation likewise, by its own share, in the tangent space at the particles' mean. 0: always
  /// reweight (the paper's).
  double gaussian_update_share = 0.01;
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
  v.flag("carry_particles", o.carry_particles);
  v.flag("velocity_drift", o.velocity_drift);
  v.flag("detector_noise", o.detector_noise);
  v.number("gaussian_update_share", o.gaussian_update_share,
           between(0.0, 1.0, "a share from 0 to 1"));
  v.section("dynamics", [&] {
    v.choice("predictor", kDynamicsPredictorNames, o.dynamics.predictor);
    v.choices("models", kBankModelNames, o.dynamics.models);
    v.choices("rotation_models", kRotationBankModelNames, o.dynamics.rotation_models);
    v.number("memory", o.dynamics.memory, positive("a positive number of s"));
    v.vector3("up", o.dynamics.up);
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
