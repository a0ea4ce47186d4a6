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
#include "opf/permanence/displacement_spread.h"

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
    std::optional<TrajectoryModel> trajectory;   ///< the `paper` predictor's fit
    std::optional<MotionPrediction> prediction;  ///< the `selected` predictor's models
    // trace of the prediction's covariance at this step (added to Q for Q~).
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

  void start_occlusion(double last_seen, const EnsembleView& ensemble);
  bool start_dynamics(Hypothesis& hypothesis);
  /// The history's estimates as samples for the motion test and the paper predictor's fit.
  std::vector<TrajectorySample> estimate_history() const;
  void follow_prediction(Hypothesis& hypothesis, double t_previous, double t);
  /// The random walk, after a drift by the recent measurements' velocity (one pass).
  void predict_with_recent_velocity(Hypothesis& hypothesis, double dt);
  /// The rotation likelihood's spread from the detector's own jitter (adaptive_rotation_noise).
  void adapt_rotation_noise(Hypothesis& hypothesis);
  void adapt_translation_noise(Hypothesis& hypothesis);
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
  std::vector<Hypothesis> hypotheses_;  ///< [0] is the object's main estimate
  std::deque<MotionSample> history_;    ///< measured frames: measurement and estimate
  DetectorJitter detector_jitter_;      ///< the detector's own noise, for the likelihood
  /// How far the object moved in a given time over its whole track (not restarted with the
  /// history): the spread of a prediction held still beyond its validation horizon.
  DisplacementSpread displacement_spread_;
  /// The dynamics module's last prediction, kept when the object was seen again where it said
  /// (no translation reset): a glimpse too brief to fit anything new continues it; a longer one
  /// that still cannot be fitted continues the axes where it reappeared confirmed (confirmed_by).
  std::optional<MotionPrediction> confirmed_motion_;
  double reappeared_at_ = 0.0;  ///< s: when it was seen again after that gap
  Eigen::Vector3d reappeared_where_ = Eigen::Vector3d::Zero();  ///< and where it was measured
  double t_ = 0.0;
  double hidden_since_ = 0.0;
  bool hidden_ = false;
  bool initialised_ = false;
};

}  // namespace opf
