#pragma once
// The Object Permanence Filter (paper Sec. III): the 6-DoF particle filter whose update, when the
// measurement is missing, uses a virtual measurement from the Object Permanence update: the
// fitted trajectory of a moving object (dynamics module) or the measurement of the object hiding
// a static one (occluder module), with an inflated observation covariance (uncertainty module)
// whose trace drives the safety alert (feedback module). The occluder module keeps hypotheses with
// probabilities: carried by each plausible occluder, or left where it was; what the camera does
// not see weighs them while hidden, and at the reappearance the most probable given the
// measurement survives.

#include "opf/core/estimator.h"
#include "opf/estimators/opf_options.h"
#include "opf/particles/pose_particle_filter.h"
#include "opf/permanence/detector_jitter.h"
#include "opf/permanence/hidden_motion.h"
#include "opf/permanence/motion_model_bank.h"
#include "opf/permanence/rotation_model_bank.h"

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace opf {

class ObjectPermanenceFilter final : public Estimator {
 public:
  /// `object` is this filter's own name in the ensemble (so it never picks itself as occluder).
  ObjectPermanenceFilter(const OpfOptions& options, std::string object, std::uint64_t seed);

  std::string_view name() const override { return "opf"; }
  Estimate initialise(double t, const mrpt::poses::CPose3D& first_measurement) override;
  Estimate step(double t, const mrpt::poses::CPose3D* measurement,
                const EnsembleView& ensemble) override;
  std::vector<Estimate> extra_hypotheses() const override;

 private:
  /// The object's main estimate or one of its occluder hypotheses: a filter and, while hidden,
  /// what moves it.
  struct Hypothesis {
    explicit Hypothesis(PoseParticleFilter f) : filter(std::move(f)) {}
    Hypothesis(const Hypothesis& other);
    Hypothesis& operator=(const Hypothesis& other);
    Hypothesis(Hypothesis&&) = default;
    Hypothesis& operator=(Hypothesis&&) = default;

    PoseParticleFilter filter;
    std::unique_ptr<HiddenMotion> motion;  ///< none while the object is measured
    HiddenStep last;                       ///< Q~ and the recovery events of the last step
    double probability = 1.0;              ///< among the object's hypotheses (they sum to one)
  };

  void restart_banks();
  /// Whether a measured position lies within the translation bank's validation gate.
  bool bank_expects(double t, const Eigen::Vector3d& position, double extra_noise) const;
  /// `extra_noise` (m): the detector's stated extra noise of the detection
  /// (Detection::extra_noise).
  void update_banks(double t, const Eigen::Vector3d& position,
                    const Eigen::Quaterniond& orientation, double extra_noise,
                    const PartialViewBias& stretch_prior);
  void take_held_measurement();
  Estimate update(double t, double dt, const mrpt::poses::CPose3D& measurement, double extra_noise,
                  const EnsembleView& ensemble);
  void start_occlusion(double last_seen, const EnsembleView& ensemble);
  /// The motion test (paper Eq. 10-11, or the fitted displacement) over the history.
  bool history_moves() const;
  /// The paper predictor's source: the Ceres fit of the history, if it can be fitted.
  std::unique_ptr<HiddenMotion> fitted_trajectory(double last_seen) const;
  std::unique_ptr<HiddenMotion> bank_mixture(PoseParticleFilter& filter);
  /// The occluder module: false when no object can hide this one. `beside_own_motion`: the main
  /// hypothesis keeps the motion it has (a moving object's) in place of `left`, and every
  /// plausible occluder carries a further one.
  bool start_occluders(const EnsembleView& ensemble, bool beside_own_motion);
  /// Moves `filter`'s particles, their mean at `mean`, to the still object's place, and returns
  /// it: the translation bank's filtered position at the last detection, whose constant-position
  /// members average the detections where the particles follow each one. With the paper's
  /// predictor (no bank), `mean` stays.
  Eigen::Vector3d move_to_bank_place(PoseParticleFilter& filter, const Eigen::Vector3d& mean) const;
  VirtualMeasurementMotion::Settings virtual_measurement_settings() const;
  /// The random walk, after a drift by the banks' velocity (one pass).
  void predict_with_bank_velocity(Hypothesis& hypothesis, double dt);
  /// The rotation likelihood's spread from the detector's own jitter (detector_noise).
  void adapt_rotation_noise(Hypothesis& hypothesis);
  void remember(double t, const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                const Estimate& estimate, double extra_noise,
                const PartialViewBias& stretch_prior = {});
  void keep_hypothesis_explaining(const Eigen::Vector3d& position);
  /// The negative information: each hypothesis whose place the camera would see, while no
  /// detection arrives, loses probability by the detector's miss probability.
  void weigh_by_what_is_not_seen(const EnsembleView& ensemble, double dt);
  /// Orders the hypotheses and drops the negligible ones (hypothesis_order), then renormalises.
  void most_probable_first();
  /// The hypotheses' probabilities, in their order.
  std::vector<double> probabilities() const;
  /// Scales the hypotheses' probabilities to sum to one.
  void normalise_probabilities();
  Estimate make_estimate(const Hypothesis& hypothesis, int index) const;

  OpfOptions options_;
  std::string object_;
  std::uint64_t seed_;
  std::uint64_t spawned_ = 0;
  std::vector<Hypothesis> hypotheses_;    ///< [0] is the object's main estimate
  std::deque<TrajectorySample> history_;  ///< the estimates of the last H measured frames
  DetectorJitter detector_jitter_;        ///< the detector's own noise, for the likelihood
  /// The motion models over the measurements (all of them, across gaps, until an occluder
  /// carried the object): the dynamics module's prediction and the visible drift.
  MotionModelBank translation_bank_;
  RotationModelBank rotation_bank_;
  std::uint64_t occlusions_ = 0;  ///< numbers each gap's draws
  /// A measurement outside the banks' gate, held back until the next one says whether it was an
  /// outlier (the next is inside: dropped) or the object moved as no model predicted (outside
  /// too: both are taken).
  struct HeldMeasurement {
    double t;
    Eigen::Vector3d position;
    Eigen::Quaterniond orientation;
    double extra_noise;
    PartialViewBias stretch_prior;
  };
  std::optional<HeldMeasurement> held_;
  double t_ = 0.0;
  double hidden_since_ = 0.0;
  /// m: how near the occluder came to this object when it hid it: the extent of an object whose
  /// detector states none (place_visibility.h).
  double hiding_radius_ = 0.0;
  /// The object's position covariance at onset: how well each hypothesis knows its place (the
  /// particles' random walk spreads them to keep them alive, not because the object moves).
  Eigen::Matrix3d place_covariance_ = Eigen::Matrix3d::Zero();
  bool hidden_ = false;
  bool initialised_ = false;
};

}  // namespace opf
