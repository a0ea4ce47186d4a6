#pragma once
// The dynamics module's predictor (this toolkit's default; the paper's Eq. 12 fit is the `paper`
// predictor): at occlusion onset it chooses, from the object's own recent history, the motion
// model that best predicts it, and extrapolates from the last estimate with an uncertainty that
// grows with the time hidden.
//
// Candidates, per world axis: constant position, constant velocity, constant acceleration and
// ballistic flight (gravity known), each fitted over several windows (seconds, so 10, 30 and
// 100 Hz logs behave alike); for rotation, constant orientation and constant angular velocity
// about the recent axis (a rotation vector growing linearly in the body frame). Each candidate is
// scored the way it will be used: fitted on the history up to an earlier origin, anchored at the
// filter's estimate there, and asked to predict the measurements up to a horizon after it, from
// origins spread over the last second (rolling-origin validation). Every fit of a translation
// model (ballistic flight: its best window; rotation: each model's best window) is refitted at
// the onset, and they are combined with weights inversely proportional to their validation errors
// (Bates and Granger), for each time ahead those made at most that far ahead: no single lucky
// score decides, a model that predicts well dominates, and each leads where it predicts best. The
// combination's validation errors, against the time they were predicted ahead, give the growth of
// the prediction's variance.

#include "opf/core/enum_names.h"
#include "opf/core/option_schema.h"
#include "opf/permanence/rotation_model.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "opf/fit/local_polynomial.h"
#include "opf/permanence/displacement_spread.h"

#include <array>
#include <deque>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opf {

enum class TranslationModel {
  kConstantPosition,
  kConstantVelocity,
  kConstantAcceleration,
  kBallistic
};
/// The words of the `model` column of estimate files.
inline constexpr EnumNames<TranslationModel, 4> kTranslationModelNames = {
    {{TranslationModel::kConstantPosition, "cp"},
     {TranslationModel::kConstantVelocity, "cv"},
     {TranslationModel::kConstantAcceleration, "ca"},
     {TranslationModel::kBallistic, "ballistic"}}};
inline constexpr EnumNames<RotationModel, 2> kRotationModelNames = {
    {{RotationModel::kConstantOrientation, "co"}, {RotationModel::kConstantAngularVelocity, "cw"}}};

inline constexpr int kTranslationModelCount = 4;
inline constexpr int kRotationModelCount = 2;

/// Short names used in result files and summaries: cp, cv, ca, ballistic; co, cw.
std::string_view to_string(TranslationModel model);
std::string_view to_string(RotationModel model);

struct MotionPredictionOptions {
  /// s of history kept and searched (measurements and the estimates at their frames).
  double history_window = 2.0;
  /// s: the fit windows tried for every model (clipped to the history).
  std::vector<double> fit_windows = {0.2, 0.4, 0.8, 1.6};
  /// s: how far ahead the validation predicts (at most a third of the history).
  double validation_horizon = 0.5;
  /// s: a validation origin this much older than the last sample weighs e^-1 of the newest: a
  /// model's recent predictions tell more about the motion the object is in now (the real clips'
  /// hidden errors fall 2-20%, the cup's at 0.6 s by a fifth). 0: every origin alike.
  double validation_memory = 0.5;
  /// Try ballistic flight under gravity as a model.
  bool ballistic = true;
  /// Try a fitted constant acceleration as a model. Its error grows as h^2 beyond the horizon it
  /// was scored on (with 1 mm noise over 0.2 s the acceleration is known to +-0.15 m/s^2: 2 cm
  /// after 0.5 s), but on real hand-held and walking motion it earns its weight (the real-video
  /// benchmark loses a third without it).
  bool constant_acceleration = true;
  /// Try a constant velocity that wanders (the constant-velocity Kalman filter's model, a filter
  /// per axis over the history) as a model: its random acceleration is the one read from the
  /// history (the intensity the prediction's uncertainty grows with) and its noise the
  /// measurements'. Where a line over a fixed window weighs its samples alike, the filter weighs
  /// the newest most, which hand-moved objects follow best.
  bool wandering_velocity = true;
  /// The wandering velocity's memories, as fractions of the one the history implies: each
  /// fraction f is one more candidate whose random acceleration is the read one over f^4 (it
  /// forgets 1 / f times faster). The read intensity is a lower bound (it must stand a standard
  /// error above zero), hence the shorter memories, doubling as the fit windows do.
  std::vector<double> wander_memories = {1.0, 0.5, 0.25};
  /// Weigh the translation models separately for each time ahead, each by its validation errors
  /// made at most that far ahead (Bates-Granger weights per horizon): the model that follows the
  /// newest motion best leads the first frames of a gap, the one that holds longest its end. Over
  /// 20 placements of the gaps in the real clips the hand-moved objects' hidden errors fall 2-9%,
  /// the walker's move by under 1%. false: one set of weights, judged on all the errors.
  bool weights_by_horizon = true;
  /// The translation models' weights on an axis go as their validation error in excess of the
  /// noise to the power -k (1: Bates and Granger's inverse-error weights, 0: equal weights), k read
  /// from what the validation shows on that axis (docs/dynamics.md, "The combination's
  /// sharpness"):
  /// - combination_sharpness where a moving model predicts best, to within
  ///   misspecified_noise_ratio times the noise's variance: a motion the models describe (a
  ///   throw, a slide), whose right model needs its weight;
  /// - misspecified_sharpness where even the best misses by twice that ratio or more: every model
  ///   is wrong (a hand's motion), their scores over the last second say less about the next, and
  ///   weights shrunk towards equal average their errors out; log-linear in the ratio between.
  ///   Shrunk among the models whose excess is within misspecified_within times the best's only
  ///   (beyond, the weights fall as Bates and Granger's): a ratio read from a short history is
  ///   mostly the fits' parameter error, and the clearly wrong models must not gain;
  /// - still_sharpness where holding still predicts best: the motion seen is jitter about a place
  ///   (a walker's depth read from her size), which the moving models would extrapolate.
  double combination_sharpness = 1.0;
  double misspecified_sharpness = 0.5;
  /// 0: combination_sharpness wherever a moving model predicts best.
  double misspecified_noise_ratio = 6.0;
  double misspecified_within = 4.0;  ///< 0: every model shrunk alike
  double still_sharpness = 2.0;
  /// Let the prediction's variance grow in proportion to the time hidden too (a1 h: the position
  /// wandering as a random walk) where the validation errors show it: a detector's centroid that
  /// drifts with the segmentation, a walker's sway. Without the term the variance's fit (h^2 and
  /// up) bends under the later errors and the first 0.1-0.2 s of a gap are the least covered (90%
  /// of the cup's and the walker's first hidden frames within 2 sqrt(trace), 96-99% with it).
  bool diffusion_growth = true;
  double gravity = 9.81;                          ///< m/s^2
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  ///< world axis opposite to gravity
  /// Multiplies the predicted standard deviations: validation errors of the chosen model are
  /// optimistic (it won on them), and a hidden object's true motion is not the model's.
  double uncertainty_scale = 1.75;
  /// s: the prediction starts at the filter's estimate (no jump at onset) and, for a fitted
  /// motion (not a constant model), settles onto the robust fit's own track with this time
  /// constant. The last estimates before an occlusion are
  /// often its worst (a half-covered object's centroid is biased towards its visible side),
  /// while the fit down-weights them. 0: onto the fit at once.
  double settle_time = 0.2;
  /// s: the measurements this close to the last one are left out of the fits and their scores;
  /// the prediction still starts at the last estimate. A camera that sees an object half covered
  /// just before it is lost biases its last centroids towards the visible side (the rendered
  /// experiments set 0.1 s); on real video with clean losses the last measurements are the most
  /// informative ones (a turn just before the loss), so the default keeps them all.
  double onset_guard = 0.0;
  /// Beyond the horizon the models were validated to, each axis's motion coasts to a stop where
  /// the validation says extrapolating stops paying (MotionPrediction::coast); off: it goes on.
  bool coast_beyond_validation = true;
  /// Beyond that horizon, while an axis's motion coasts (holds still), its variance grows at
  /// least as the object's own track says it moves in that time (MotionPrediction::track_spread,
  /// filled by the filter); off: the growth fitted up to the horizon goes on alone.
  bool spread_beyond_validation = true;
  int robust_iterations = 3;  ///< Huber reweightings per fit; 0: plain least squares
};

/// The settings file's `opf.dynamics:` keys of the selected predictor (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, MotionPredictionOptions& o) {
  v.number("history_window", o.history_window, positive("a positive number of s"));
  v.numbers("fit_windows", o.fit_windows, positive("positive numbers of s"));
  v.number("validation_horizon", o.validation_horizon, positive("a positive number of s"));
  v.number("validation_memory", o.validation_memory,
           non_negative("seconds >= 0 (0: every validation origin alike)"));
  v.flag("ballistic", o.ballistic);
  v.flag("constant_acceleration", o.constant_acceleration);
  v.flag("wandering_velocity", o.wandering_velocity);
  v.numbers("wander_memories", o.wander_memories, positive("positive fractions"));
  v.flag("weights_by_horizon", o.weights_by_horizon);
  v.number("combination_sharpness", o.combination_sharpness,
           between(0.0, 4.0, "a number from 0 (equal weights) to 4"));
  v.number("misspecified_sharpness", o.misspecified_sharpness,
           between(0.0, 4.0, "a number from 0 (equal weights) to 4"));
  v.number("misspecified_noise_ratio", o.misspecified_noise_ratio,
           non_negative("a ratio >= 0 (0: off)"));
  v.number("misspecified_within", o.misspecified_within,
           non_negative("a factor >= 0 (0: every model)"));
  v.number("still_sharpness", o.still_sharpness,
           between(0.0, 4.0, "a number from 0 (equal weights) to 4"));
  v.flag("diffusion_growth", o.diffusion_growth);
  v.number("gravity", o.gravity, non_negative("m/s^2 >= 0"));
  v.vector3("up", o.up);
  v.number("uncertainty_scale", o.uncertainty_scale, positive());
  v.number("settle_time", o.settle_time, non_negative("seconds >= 0"));
  v.number("onset_guard", o.onset_guard, non_negative("seconds >= 0"));
  v.flag("coast_beyond_validation", o.coast_beyond_validation);
  v.flag("spread_beyond_validation", o.spread_beyond_validation);
  v.integer("robust_iterations", o.robust_iterations, between(0, 20, "an integer from 0 to 20"));
}

/// The powers (h, h^2, h^3, h^4) of the time ahead the prediction's variance grows with.
inline Eigen::Vector4d growth_powers(double h) {
  return {h, h * h, h * h * h, h * h * h * h};
}

/// One frame of an object's history: its measurement and the filter's estimate after it.
struct MotionSample {
  double t = 0.0;
  Eigen::Vector3d measured_position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond measured_orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d estimated_position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond estimated_orientation = Eigen::Quaterniond::Identity();
};

/// One model of a combination: its fit and its share of the prediction.
struct WeightedFit {
  /// Its share judged on every validation error (for reports and the velocity's variance).
  double weight = 0.0;
  /// Its share of the prediction h seconds after the last measurement it was fitted to, at
  /// h = (k + 1) MotionPrediction::horizon_step for k = 0, 1, ...: judged on the validation errors
  /// made at most that far ahead, since a model that follows the newest motion best need not be
  /// the one that holds longest. Linear between the nodes, the first node's before it and the
  /// last's after it; empty: `weight` throughout.
  std::vector<double> weight_by_horizon;
  LocalPolynomial fit;
  /// s of history it was fitted to; for a wandering velocity, its memory fraction.
  double window = 0.0;
  /// A fitted motion (order >= 1) says where the object is now, and the prediction settles onto
  /// its track; a constant model's track is the mean of its window, which a moving object has
  /// left.
  bool settles = false;
};

/// The models combined at the onset, anchored there: everything as a function of the time h >= 0
/// since the last measurement.
struct MotionPrediction {
  /// Per world axis, the models and their weights (summing to 1); the translation fits are of
  /// positions relative to the last measurement.
  std::array<std::vector<WeightedFit>, 3> translation;
  /// Rotation vectors in the body frame of the last measured orientation.
  std::vector<WeightedFit> rotation;
  /// For reports: per axis the model whose windows weigh the most, the most elaborate of the
  /// three, and the rotation model with the largest weight.
  std::array<TranslationModel, 3> translation_models{};
  TranslationModel translation_model = TranslationModel::kConstantPosition;
  RotationModel rotation_model = RotationModel::kConstantOrientation;
  double translation_score = 0.0;  ///< RMS validation error of the combination, m
  double rotation_score = 0.0;     ///< rad
  double t_last = 0.0;             ///< time of the last measurement
  /// The prediction variance is (a1 h + a2 h^2 + a3 h^3 + a4 h^4) uncertainty_scale^2, fitted to
  /// the combination's validation errors: per axis, a row (a1, a2, a3, a4); for rotation, the
  /// mean over the body axes.
  Eigen::Matrix<double, 3, 4> translation_growth = Eigen::Matrix<double, 3, 4>::Zero();
  Eigen::Vector4d rotation_growth = Eigen::Vector4d::Zero();
  double uncertainty_scale = 1.0;
  /// The estimate at the last measurement, where the prediction starts.
  Eigen::Vector3d anchor_position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond anchor_orientation = Eigen::Quaterniond::Identity();
  /// The last measurement the fits used, their origin.
  Eigen::Vector3d measured_position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond measured_orientation = Eigen::Quaterniond::Identity();
  double settle_time = 0.0;
  /// Time of the last measurement the fits used (before t_last when the onset guard left some
  /// out), from which the models' shares by horizon count.
  double t_fitted = 0.0;
  /// s between the nodes of WeightedFit::weight_by_horizon.
  double horizon_step = 0.0;
  /// The time up to which the models were validated (t_fitted + the validation horizon H).
  double validated_until = 0.0;
  /// Per world axis, s: beyond validated_until the models' motion coasts to a stop with this
  /// time constant (infinite: it goes on; 0: it stops there). With rho the combination's RMS
  /// validation error at H over holding still's (both in excess of the measurement noise), an
  /// error that grows as h^2 against a motion that grows as h (a velocity that wanders) makes
  /// rho grow in proportion to h: extrapolating stops paying at H / rho, and the coast ends the
  /// motion about there, H (1 - rho) / rho beyond H. A line predicted to within the noise goes
  /// on; a hand (rho 0.3-1) stops within a second; no better than holding still (rho >= 1), or
  /// not moving beyond the noise, it stops at H. Free flight never coasts.
  Eigen::Vector3d coast = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  /// How far the object has moved in a given time over its track (empty: unknown). Beyond
  /// validated_until, for the time an axis's motion holds still instead of going on (all of it
  /// where the axis stops at once, none where it goes on), the variance grows at least by this:
  /// from the validation horizon on, where the fitted growth is an extrapolation, holding still
  /// is off by what the object was seen to move.
  DisplacementProfile track_spread;

  /// The time the models of `axis` are read at, h seconds after the last measurement.
  double model_time(double h, int axis) const;

  /// A model's share of the predicted pose at time t.
  double weight_at(const WeightedFit& model, double t) const;

  /// The predicted pose h seconds after the last measurement: the anchor at h = 0, moved by the
  /// models and settling onto the fitted motions' tracks.
  Eigen::Vector3d position(double h) const;
  Eigen::Quaterniond orientation(double h) const;
  /// Per-axis variance of position(h) (m^2) and per-axis variance of the body-frame rotation
  /// (rad^2): how far the object may be from the prediction. Beyond the validation horizon the
  /// translation's is at least its value there plus track_spread over the time held still.
  Eigen::Vector3d translation_variance(double h) const;
  double rotation_variance(double h) const;
};

/// Chooses and fits the models on `history` (oldest first, strictly increasing times). Returns
/// nothing when the history is too short to validate anything (under four samples, or spanning
/// less than three frames' worth of time).
std::optional<MotionPrediction> predict_motion(std::span<const MotionSample> history,
                                               const MotionPredictionOptions& options);

/// The same models continued from a later moment: the object was seen again at `t_last` at the
/// estimate (`position`, `orientation`) where the prediction said it would be, too briefly to fit
/// anything new. The prediction then starts there, moves by the models' own change from that
/// time on (no settling: the glimpse placed it), and its uncertainty grows afresh.
MotionPrediction continued(const MotionPrediction& prediction, double t_last,
                           const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation);

/// The prediction as the object's reappearance left it: at time `t` it was measured at
/// `measured`. Per world axis, its models' motion is kept where it put the object nearer that
/// measurement than holding still at its anchor would have, and dropped otherwise (the axis then
/// holds still when the motion is continued): a motion the gap refuted is not carried into the
/// next one.
MotionPrediction confirmed_by(MotionPrediction prediction, double t,
                              const Eigen::Vector3d& measured);

/// The velocity and body-frame angular velocity of the last `window` seconds of `history` (for the
/// particles' drift while the object is visible): per channel the slope of a least-squares line,
/// shrunk by its significance, or, where a quadratic's curvature stands 10 standard errors out of
/// the noise (a thrown object under gravity), the quadratic's slope at the last sample. Nothing
/// when fewer than three samples lie in the window.
struct RecentVelocity {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();   ///< m/s, world frame
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  ///< rad/s, body frame of the last sample
};
std::optional<RecentVelocity> recent_velocity(const std::deque<MotionSample>& history,
                                              double window);

/// The heaviest models, for reports: per axis x, y, z, then rotation, e.g. "cv,cv,cp/cw".
std::string describe(const MotionPrediction& prediction);

/// Throws std::invalid_argument naming the first option out of range.
void validate(const MotionPredictionOptions& options);

}  // namespace opf
