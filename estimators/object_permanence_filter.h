#pragma once
// The Object Permanence Filter (paper Sec. III): the 6-DoF particle filter whose update, when the
// measurement is missing, uses a virtual measurement from the Object Permanence update: the
// fitted trajectory of a moving object (dynamics module) or the measurement of the object hiding
// a static one (occluder module), with an inflated observation covariance (uncertainty module)
// whose trace drives the safety alert (feedback module). Two equally likely occluders spawn a
// second hypothesis; the one that explains the object's reappearance survives.

#include "opf/core/estimator.h"
#include "opf/estimators/opf_options.h"
#include "opf/particles/pose_particle_filter.h"
#include "opf/permanence/detector_jitter.h"
#include "opf/permanence/mixture_particle_motion.h"
#include "opf/permanence/motion_model_bank.h"
#include "opf/permanence/rotation_model_bank.h"

#include <cstdint>
#include <deque>
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
  enum class Source { kMeasurement, kTrajectory, kOccluder, kNone };

  struct Hypothesis {
    Hypothesis(PoseParticleFilter f, CovarianceInflation i)
        : filter(std::move(f)), inflation(std::move(i)) {}

    PoseParticleFilter filter;
    CovarianceInflation inflation;
    Source source = Source::kMeasurement;
    std::optional<TrajectoryModel> trajectory;     ///< the `paper` predictor's fit
    std::optional<MixtureParticleMotion> mixture;  ///< the bank's: the particles follow it
    // The trace the bank's prediction added to the cloud's covariance (added to Q for Q~).
    double prediction_trace = 0.0;
    std::string occluder;
    // The occluder's pose when the carry starts (at onset, or at its closest approach with
    // carry_from_departure) and this object's pose at onset: the hidden object is carried
    // rigidly with the occluder's rotation since then (and, with keep_offset, at that offset).
    Eigen::Vector3d occluder_position_at_onset = Eigen::Vector3d::Zero();
    Eigen::Quaterniond occluder_orientation_at_onset = Eigen::Quaterniond::Identity();
    Eigen::Vector3d position_at_onset = Eigen::Vector3d::Zero();
    Eigen::Quaterniond orientation_at_onset = Eigen::Quaterniond::Identity();
    // carry_from_departure: false while the occluder closes in; its closest horizontal distance.
    bool carrying = true;
    double closest_distance = 0.0;
    // Carried at its whole offset from the occluder (keep_offset, or a cover at its level that
    // waited for its departure), turned with it.
    bool at_offset = false;
    // The carrier's pose at the previous step (the trajectory's, or the occluder's estimate).
    std::optional<Eigen::Vector3d> last_carrier_position;
    Eigen::Quaterniond last_carrier_orientation = Eigen::Quaterniond::Identity();
    // Recent (t, position) of the occluder's estimate, spanning the speed window.
    std::deque<std::pair<double, Eigen::Vector3d>> carrier_track;
    // What the last step had to do to stay usable (the mode column's "+reset" and so on).
    RecoveryEvents recovery;
  };

  struct VirtualMeasurement {
    Eigen::Vector3d position;
    Eigen::Quaterniond orientation;
    double speed = 0.0;  ///< m/s of the carrier, for the uncertainty module
    // The motion the carrier made since the previous step (world frame), for carry_particles:
    // from `carrier_from` to `carrier_to`, turning by `carrier_rotation` about it.
    Eigen::Vector3d carrier_from = Eigen::Vector3d::Zero();
    Eigen::Vector3d carrier_to = Eigen::Vector3d::Zero();
    Eigen::Quaterniond carrier_rotation = Eigen::Quaterniond::Identity();
  };

  void restart_banks();
  /// Whether a measured position lies within the translation bank's validation gate.
  bool bank_expects(double t, const Eigen::Vector3d& position) const;
  void update_banks(double t, const Eigen::Vector3d& position,
                    const Eigen::Quaterniond& orientation);
  void start_occlusion(double last_seen, const EnsembleView& ensemble);
  /// The motion test (paper Eq. 10-11, or the fitted displacement) over the history.
  bool history_moves() const;
  /// The paper predictor: the Ceres fit of the history, if it can be fitted.
  bool start_trajectory(Hypothesis& hypothesis, double last_seen);
  /// The bank predictor: the particles start following the banks' mixture.
  void start_mixture(Hypothesis& hypothesis);
  bool start_occluders(const EnsembleView& ensemble);
  void follow_mixture(Hypothesis& hypothesis, double t_previous, double t);
  /// The random walk, after a drift by the banks' velocity (one pass).
  void predict_with_bank_velocity(Hypothesis& hypothesis, double dt);
  /// The rotation likelihood's spread from the detector's own jitter (adaptive_rotation_noise).
  void adapt_rotation_noise(Hypothesis& hypothesis);
  void remember(double t, const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                const Estimate& estimate);
  void follow_occluder(Hypothesis& hypothesis, const std::string& occluder,
                       const Estimate& occluder_estimate, const EnsembleView& ensemble) const;
  std::optional<VirtualMeasurement> virtual_measurement(Hypothesis& hypothesis, double t,
                                                        const EnsembleView& ensemble);
  void keep_hypothesis_explaining(const Eigen::Vector3d& position);
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
  };
  std::optional<HeldMeasurement> held_;
  double t_ = 0.0;
  double hidden_since_ = 0.0;
  bool hidden_ = false;
  bool initialised_ = false;
};

}  // namespace opf
