#pragma once
// A bank of linear-Gaussian motion models for an object's translation, combined by Bayesian model
// averaging: per world axis, each model (axis_motion_model.h) at a few stated intensities is a
// member with its own Kalman filter over the object's visible history, weighted by how well it
// predicted each measurement one step ahead. No intensity is tuned on data: the grid is stated
// here and the data weigh its members.
//
// The members, per axis (each white-noise density times options.intensity_scale):
//   constant position   q in {0.001, 0.01, 0.1} m/s/sqrt(Hz)       (0.1, 1, 10 x 0.01)
//   constant velocity   q in {0.03, 0.3, 3} m/s^2/sqrt(Hz)         (0.1, 1, 10 x 0.3)
//   damped velocity     q in {0.03, 0.3, 3} m/s^2/sqrt(Hz) x T in {0.3, 1, 3} s
//   ballistic           q in {0.03, 0.3, 3} m/s^2/sqrt(Hz), g = -9.81 up[axis] m/s^2
// The bases: a still object on a table or in a hand jitters by millimetres a second (0.01 m/s per
// sqrt(Hz) is 1 cm after 1 s); a hand-carried object changes its velocity by about 0.3 m/s within
// a second (0.3 m/s^2/sqrt(Hz) over 1 s); a decade either side covers resting to thrown. The time
// constants span a push that dies out within a frame-gap (0.3 s) to a glide (3 s). On an axis
// that gravity does not reach (g = 0), the ballistic model is the constant-velocity model; its
// members are left out there when constant velocity is in the bank, so that it is not counted
// twice.
//
// Weights (model_weights.h): each model has the prior 1 / (models on the axis), shared equally by
// its members (pi_j). At each measurement, after a step dt, every member predicts and updates,
// and with its innovation r_j and variance S_j
//
//   log w_j <- lambda log w_j + (1 - lambda) log pi_j + log t_1(r_j; 0, S_j),
//   lambda = exp(-dt / T_memory),
//
// then normalised and floored at 1e-12 (renormalised). The detector's noise is taken as Student-t
// with one degree of freedom (kBankNoiseDof; each member's update is
// kalman::update_covariance_student_t), so that one wild detection neither drags a member nor
// hands the weight to the widest ones; a member that two detections in a row find outside its
// 99.9% gate restarts from them (kSurprisesToRestart), so that no member is lost for good. The
// forgetting is stated in continuous time: n frames of dt forget as one of n dt. With the prior
// uniform over members, the prior term is a constant that the normalisation removes.
//
// A partial view (a detection stating an extra noise e) is off by e s: each member carries the
// bias s ~ N(0, 1) as a third state, constant over consecutive partial views (H = [1 0 e]), and
// forgets it at a clean view or a gap (end_partial_views), so that a partly covered object's
// centroid lagging frame after frame is read as the bias it is, not as a change of velocity.

#include "opf/motion/axis_motion_model.h"
#include "opf/permanence/model_weights.h"
#include "opf/permanence/motion_model_bank_options.h"
#include "opf/permanence/predictive_mixture.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace opf {

/// Constant position's base velocity density (m/s/sqrt(Hz)).
inline constexpr double kBankPositionNoiseBase = 0.01;
/// The other models' base acceleration density (m/s^2/sqrt(Hz)).
inline constexpr double kBankAccelerationNoiseBase = 0.3;
/// The floor of a member's probability (model_weights.h).
inline constexpr double kBankWeightFloor = kModelWeightFloor;

/// The predictive mixture for a horizon, per world axis.
struct BankPrediction {
  std::array<AxisMixture, 3> axes;

  Eigen::Vector3d mean() const;
  Eigen::Vector3d variance() const;
};

/// The bias of the current stretch of partial views in units of their stated extra noise: a
/// detection with extra noise e is off by e s (per axis; s ~ N(0, 1) when the stretch begins).
struct PartialViewBias {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double variance = 1.0;
};

class MotionModelBank {
 public:
  /// Throws std::invalid_argument naming the first bad option.
  explicit MotionModelBank(const MotionModelBankOptions& options = {});

  /// A measured position (m) at time t (s), not before the last one. The first starts every
  /// member's filter (position measured, velocity 0 with options.initial_velocity_std, constant
  /// position's pinned at 0) with the prior weights; a later one steps every member across the
  /// interval (a gap just predicts across) and updates it and the weights.
  /// `extra_noise` (m): the noise the detector states for this detection beyond its usual (a
  /// partial view's): the scale of the bias s that a stretch of partial views shares (each
  /// member's third state, PartialViewBias), a clean view ending the stretch.
  /// `stretch_prior`: s's prior when this detection begins a stretch of partial views.
  void update(double t, const Eigen::Vector3d& position, double extra_noise = 0.0,
              const PartialViewBias& stretch_prior = {});
  /// Whether the last update was a partial view with no gap since (a stretch goes on).
  bool in_partial_views() const { return in_partial_views_; }
  /// The partial views' bias s: its mixture mean per axis and variance (averaged over the axes).
  PartialViewBias partial_view_bias() const;
  /// Ends a stretch of partial views (a gap: the object comes back seen from another side).
  void end_partial_views();

  bool initialised() const { return initialised_; }
  /// The time of the last update (s).
  double last_time() const { return t_; }

  /// The mixture's mean velocity per world axis (m/s) at the last update: sum_j w_j v_j.
  Eigen::Vector3d velocity() const;
  /// The predictive mixture of the position `horizon` s (>= 0) after the last update: per axis,
  /// every member's weight, mean and variance (of the position itself; its measurement adds
  /// options.observation_noise^2).
  BankPrediction predict(double horizon) const;
  /// The same into `out`, its vectors reused.
  void predict(double horizon, BankPrediction& out) const;
  /// How much the predictive mixture's variance per world axis grows from the last update to
  /// `horizon` s after it (m^2): predict(horizon).variance() less predict(0).variance(), without
  /// building the mixtures.
  Eigen::Vector3d variance_growth(double horizon) const;
  /// One member's prediction (its weight included), member indices as members(axis); by the
  /// member's last step when the horizon is that interval.
  MemberPrediction member_prediction(int axis, std::size_t index, double horizon) const;

  /// The members on an axis, in the order of the weights.
  std::span<const AxisMotionModel> members(int axis) const { return models_[axis]; }
  /// Their probabilities (summing to 1).
  std::span<const double> weights(int axis) const { return weights_[axis].weights(); }
  /// The total probability of a model's members on an axis.
  double model_weight(int axis, MotionModel model) const;
  /// The member that a uniform draw in [0, 1) maps to, each taking its weight's share of [0, 1)
  /// (weighted_choice.h): a particle's member, drawn at the onset of a gap.
  std::size_t sample_member(int axis, double uniform01) const;

  const MotionModelBankOptions& options() const { return options_; }

 private:
  struct Filter {
    kalman::Vector<2> mean;
    kalman::Matrix<2> covariance;
    /// The partial views' bias s (a detection off by extra_noise s, s ~ N(0, 1), one s for a
    /// stretch of consecutive partial views): its mean, variance and covariance with (p, v).
    double bias = 0.0;
    double bias_variance = 1.0;
    kalman::Vector<2> bias_covariance = kalman::Vector<2>::Zero();
    /// s afresh: N(0, 1), independent of (p, v).
    void forget_bias() {
      bias = 0.0;
      bias_variance = 1.0;
      bias_covariance.setZero();
    }
    int surprises = 0;  ///< consecutive measurements outside the member's gate
    /// The model's step over the last update's interval (a copy of its shape's: the update
    /// reads it beside the member's state).
    AxisMotionStep step;
  };
  /// Starts a member from its first position (dt = 0: velocity 0 with initial_velocity_std), or
  /// restarts one that has lost the object from the last two positions (two-point differencing:
  /// the velocity is their slope); v pinned at 0 for constant position.
  void start(Filter& filter, MotionModel model, double position, double previous, double dt,
             double r) const;
  /// Member f's update with the axis's measurement z, its stated extra noise and the detector's
  /// usual noise (variance r); returns the Student-t correction (its log-likelihood left out).
  kalman::Correction<3, 1> update_member(Filter& f, double z, double extra_noise, double r) const;
  /// update_member's (p, v) update when the detection states no extra noise.
  kalman::Correction<3, 1> update_position(Filter& f, double z, double r) const;
  /// member_prediction without its checks, by `step`, the member's over the horizon.
  MemberPrediction predicted_member(int axis, std::size_t index, const AxisMotionStep& step) const;
  /// Every member's step over dt, by shape (the cached ones at the last update's interval).
  const std::vector<AxisMotionStep>& steps_at(double dt,
                                              std::vector<AxisMotionStep>& scratch) const;

  MotionModelBankOptions options_;
  std::array<std::vector<AxisMotionModel>, 3> models_;
  /// The distinct models over the three axes (the axes across gravity hold the same members),
  /// each member's index among them, and their steps over the last update's interval, computed
  /// together (steps_over) and reused while frames keep one rate.
  std::vector<AxisMotionModel> shapes_;
  std::array<std::vector<std::size_t>, 3> shape_of_;
  double steps_dt_ = -1.0;
  std::vector<AxisMotionStep> steps_;
  std::array<std::vector<Filter>, 3> filters_;
  std::vector<ModelWeights> weights_;  ///< one per axis
  /// Scratch per member on an axis: S, d^2, then their log-densities.
  std::vector<double> determinants_, squared_distances_, log_likelihoods_;
  /// The detector's noise on one axis (kBankNoiseDof).
  kalman::StudentTNoise noise_model_ = kalman::student_t_noise<1>(kBankNoiseDof);
  Eigen::Vector3d last_position_ = Eigen::Vector3d::Zero();
  bool in_partial_views_ = false;  ///< the last update was a partial view (no gap since)
  double t_ = 0.0;
  bool initialised_ = false;
};

}  // namespace opf
