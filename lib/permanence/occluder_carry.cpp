#include "opf/permanence/occluder_carry.h"

#include "opf/core/pose_conversion.h"
#include "opf/permanence/partial_view.h"

#include <algorithm>
#include <cmath>

namespace opf {
namespace {

const Estimate* find_estimate(const EnsembleView& ensemble, const std::string& object) {
  for (const Estimate& e : ensemble.previous_estimates)
    if (e.object == object) return &e;
  return nullptr;
}

// The occluder's pose as the carry reads it: its position from its measurement this frame when
// it has one (its estimate is a frame old and lags a moving occluder), its orientation from its
// filtered estimate when it has one and `orientation_from_estimate` (a single detection's
// rotation noise would bias the whole carry).
struct CarrierPose {
  Eigen::Vector3d position;
  Eigen::Quaterniond orientation;
};

// A detection's partial view is read as one (partial_view.h) when `stated`.
CarrierPose carrier_pose(const Detection* detection, const Estimate* estimate,
                         const EnsembleView& ensemble, const OccluderOptions& options,
                         bool stated) {
  const mrpt::poses::CPose3D& for_position = detection ? detection->pose : estimate->pose.mean;
  const mrpt::poses::CPose3D& for_orientation =
      (estimate && (options.orientation_from_estimate || !detection)) ? estimate->pose.mean
                                                                      : detection->pose;
  CarrierPose pose{translation_of(for_position), orientation_of(for_orientation).normalized()};
  if (detection && stated)
    pose.position = partial_view_centre(pose.position, detection->extra_noise, detection->object,
                                        ensemble, options)
                        .position;
  return pose;
}

double horizontal_distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                           const Eigen::Vector3d& up) {
  const Eigen::Vector3d d = a - b;
  return (d - up * up.dot(d)).norm();
}

// The time in [from, to] at which `track` passes nearest `place` horizontally, to a hundredth of
// the span: a cover's closest approach read from its smoothed track, where the least distance among
// its noisy detections would pick one whose noise points at the object.
double closest_approach(const TrajectoryModel& track, double from, double to,
                        const Eigen::Vector3d& place, const Eigen::Vector3d& up) {
  double at = from;
  double least = horizontal_distance(track.position(from), place, up);
  for (int k = 1; k <= 100; ++k) {
    const double t = from + (to - from) * k / 100;
    const double d = horizontal_distance(track.position(t), place, up);
    if (d < least) least = d, at = t;
  }
  return at;
}

}  // namespace

OccluderCarry::OccluderCarry(const Settings& settings, const OccluderOptions& options,
                             const Eigen::Vector3d& up, const Eigen::Vector3d& position_at_onset,
                             const Eigen::Quaterniond& orientation_at_onset, std::string occluder,
                             const Estimate& occluder_estimate, const EnsembleView& ensemble)
    : VirtualMeasurementMotion(settings),
      options_(options),
      stated_noise_(settings.stated_noise),
      speed_window_(settings.uncertainty.speed_window),
      up_(up.normalized()),
      occluder_(std::move(occluder)),
      position_at_onset_(position_at_onset),
      orientation_at_onset_(orientation_at_onset) {
  const Detection* occluder_detection = ensemble.frame.find(occluder_);
  const CarrierPose reference = carrier_pose(occluder_detection, &occluder_estimate, ensemble,
                                             options_, settings.stated_noise);
  occluder_position_at_onset_ = last_carrier_position_ = reference.position;
  occluder_orientation_at_onset_ = last_carrier_orientation_ = reference.orientation;
  // A cover at the object's level (a cup slid over a ball) moves it only by pushing it: it waits
  // for the occluder's departure. One above it (a hand, a lifted tray) is followed from onset.
  const bool level = std::abs(up_.dot(reference.position - position_at_onset_)) <= options_.reach;
  const bool wait = options_.carry_from_departure && level;
  waits_ = wait;
  at_offset_ = options_.keep_offset || wait;
  closest_distance_ = horizontal_distance(reference.position, position_at_onset_, up_);
  start_time_ = ensemble.frame.t;
  if (occluder_detection) record_around_start(start_time_, reference.position);
}

bool OccluderCarry::departed(double t, const Eigen::Vector3d& position,
                             const Eigen::Quaterniond& orientation) {
  // Still closing in over the object: it stays where it was covered, and the carry will start
  // from the occluder's closest approach. Read from its measurements: its filtered estimate lags a
  // cup closing in and overshoots where it stops short.
  const double d = horizontal_distance(position, position_at_onset_, up_);
  if (d <= closest_distance_) {
    closest_distance_ = d;
    start_time_ = t;
    start_fitted_ = false;
    occluder_position_at_onset_ = last_carrier_position_ = position;
    occluder_orientation_at_onset_ = last_carrier_orientation_ = orientation;
  }
  // Departed: further from the object than at the closest approach, and moved off that place by
  // the margin (tangentially too: a cup that stopped beside the ball and drags it sideways barely
  // changes its distance).
  const bool receding = d > closest_distance_;
  const bool moved =
      horizontal_distance(position, occluder_position_at_onset_, up_) > options_.departure_margin;
  return receding && moved;
}

void OccluderCarry::record_around_start(double t, const Eigen::Vector3d& detected_position) {
  // Until the window after the start is complete; a frame counts once (the onset's comes twice).
  if (t > start_time_ + speed_window_ || (!around_start_.empty() && t <= around_start_.back().t))
    return;
  around_start_.push_back({.t = t, .position = detected_position});
  std::erase_if(around_start_,
                [&](const TrajectorySample& s) { return s.t < start_time_ - speed_window_; });
  start_fitted_ = false;
}

void OccluderCarry::fit_start() {
  start_fitted_ = true;
  if (around_start_.size() < 3) return;  // the detection stands
  TrajectoryFitOptions quadratic;
  quadratic.translation_order = 2;
  quadratic.rotation_order = 0;
  try {
    const TrajectoryModel track = fit_trajectory(around_start_, quadratic);
    const double at = waits_ ? closest_approach(track, around_start_.front().t,
                                                around_start_.back().t, position_at_onset_, up_)
                             : start_time_;
    occluder_position_at_onset_ = track.position(at);
  } catch (const std::exception&) {
    // No usable fit: the detection stands.
  }
}

double OccluderCarry::speed(double t, const Eigen::Vector3d& position) {
  carrier_track_.emplace_back(t, position);
  while (carrier_track_.size() > 2 && t - carrier_track_[1].first >= speed_window_)
    carrier_track_.pop_front();
  // Divided by at least the window: right after onset the baseline is a frame or two, and a still
  // occluder's jitter over one frame would read as speed.
  const auto& [t0, p0] = carrier_track_.front();
  return (position - p0).norm() / std::max(t - t0, std::max(speed_window_, 1e-9));
}

std::optional<VirtualMeasurementMotion::Measurement> OccluderCarry::measure(
    double t, const EnsembleView& ensemble) {
  // The occluder's measurement this frame (the paper's y_k^j), or its estimate when it is hidden
  // itself (a chain of occlusions).
  carrier_offset_.reset();
  const Estimate* occluder_estimate = find_estimate(ensemble, occluder_);
  const Detection* occluder_detection = ensemble.frame.find(occluder_);
  if (!occluder_estimate && !occluder_detection) return std::nullopt;
  const CarrierPose occluder =
      carrier_pose(occluder_detection, occluder_estimate, ensemble, options_, stated_noise_);
  // Judged afresh every frame: a cover that comes closer again than where it seemed to depart
  // (its detection's jitter) is still closing in, and the carry restarts from its new closest
  // approach.
  const bool waiting = waits_ && !departed(t, occluder.position, occluder.orientation);
  if (occluder_detection) record_around_start(t, occluder.position);
  if (waiting) return std::nullopt;
  if (!start_fitted_) fit_start();
  const Eigen::Quaterniond carried =
      occluder.orientation * occluder_orientation_at_onset_.conjugate();
  Measurement z;
  z.position = occluder.position;
  const Eigen::Vector3d onset_offset = carried * (position_at_onset_ - occluder_position_at_onset_);
  if (at_offset_)
    z.position += onset_offset;
  else if (options_.keep_depth)
    z.position += up_ * up_.dot(onset_offset);  // only the offset's height: it keeps its own
  z.orientation = (carried * orientation_at_onset_).normalized();
  z.carrier_from = last_carrier_position_;
  z.carrier_to = occluder.position;
  z.carrier_rotation = (occluder.orientation * last_carrier_orientation_.conjugate()).normalized();
  z.about_carrier = at_offset_;
  // Its speed for the uncertainty module from the filtered estimate: a still occluder reads as
  // still rather than jittering with its measurement noise.
  z.speed = speed(
      t, occluder_estimate ? translation_of(occluder_estimate->pose.mean) : occluder.position);
  last_carrier_position_ = occluder.position;
  last_carrier_orientation_ = occluder.orientation;
  carrier_offset_ = occluder.position - z.position;
  return z;
}

}  // namespace opf
