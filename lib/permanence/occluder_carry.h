#pragma once
// The occluder module's carry (paper Sec. III-B.2): a static hidden object follows the object
// that hides it, the occluder's measurement (or estimate) being its virtual measurement. A cover
// at the object's level (a cup slid over a ball) is waited for until it departs, then carried
// from its closest approach at that offset; one above it (a hand, a lifted tray) is followed from
// onset. The choice of occluder is occluder_selection.h's.

#include "opf/fit/trajectory_fit.h"
#include "opf/permanence/hidden_motion.h"
#include "opf/permanence/occluder_selection.h"

#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace opf {

class OccluderCarry final : public VirtualMeasurementMotion {
 public:
  /// The hidden object's pose at onset, the occluder's name and its estimate then; `up` is the
  /// world's vertical.
  OccluderCarry(const Settings& settings, const OccluderOptions& options, const Eigen::Vector3d& up,
                const Eigen::Vector3d& position_at_onset,
                const Eigen::Quaterniond& orientation_at_onset, std::string occluder,
                const Estimate& occluder_estimate, const EnsembleView& ensemble);

  std::unique_ptr<HiddenMotion> clone() const override {
    return std::make_unique<OccluderCarry>(*this);
  }
  EstimateMode mode() const override { return EstimateMode::kCarried; }
  /// The occluder that carries the object, by its name in the ensemble.
  std::string label() const override { return occluder_; }
  std::optional<Eigen::Vector3d> carrier_offset() const override { return carrier_offset_; }

 private:
  std::optional<Measurement> measure(double t, const EnsembleView& ensemble) override;
  /// Whether the carry has begun (a cover closing in is waited for until it departs).
  bool departed(double t, const Eigen::Vector3d& occluder_position,
                const Eigen::Quaterniond& orientation);
  double speed(double t, const Eigen::Vector3d& position);
  /// Adds the occluder's detected position at t to those around the carry's start.
  void record_around_start(double t, const Eigen::Vector3d& detected_position);
  /// Where the occluder was when the carry started, from those detections: at the start, or for a
  /// cover at the fitted track's closest approach. Fitted once the carry runs (not while a cover
  /// closes in, which moves the start), again after each new detection in the window.
  void fit_start();

  OccluderOptions options_;
  bool stated_noise_;    ///< the carrier's partial views read as such
  double speed_window_;  ///< s, the uncertainty module's
  Eigen::Vector3d up_;
  std::string occluder_;
  // The occluder's pose when the carry starts (at onset, or at its closest approach) and this
  // object's pose at onset: the object is carried rigidly with the occluder's rotation since then.
  Eigen::Vector3d occluder_position_at_onset_;
  Eigen::Quaterniond occluder_orientation_at_onset_;
  Eigen::Vector3d position_at_onset_;
  Eigen::Quaterniond orientation_at_onset_;
  bool waits_ = false;           ///< a cover: carries only once it departs
  double closest_distance_ = 0;  ///< its closest horizontal distance so far
  bool at_offset_ = false;       ///< carried at its whole offset, turned about the occluder
  /// The carrier from the object in the last step's carry; none while a cover closes in.
  std::optional<Eigen::Vector3d> carrier_offset_;
  Eigen::Vector3d last_carrier_position_;
  Eigen::Quaterniond last_carrier_orientation_;
  // Recent (t, position) of the occluder's estimate, spanning the speed window.
  std::deque<std::pair<double, Eigen::Vector3d>> carrier_track_;
  // When the carry starts, and the occluder's detections within the speed window either side:
  // where the occluder was then is their quadratic fit (a local polynomial smoother), since one
  // detection's noise would offset the object for the whole carry.
  double start_time_ = 0;
  std::vector<TrajectorySample> around_start_;
  bool start_fitted_ = false;
};

}  // namespace opf
