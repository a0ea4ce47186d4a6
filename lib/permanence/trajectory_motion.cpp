#include "opf/permanence/trajectory_motion.h"

#include <utility>

namespace opf {

TrajectoryMotion::TrajectoryMotion(const Settings& settings, TrajectoryModel model,
                                   double last_seen)
    : VirtualMeasurementMotion(settings),
      model_(std::move(model)),
      last_position_(model_.position(last_seen)),
      last_orientation_(model_.orientation(last_seen)) {}

std::optional<VirtualMeasurementMotion::Measurement> TrajectoryMotion::measure(
    double t, const EnsembleView&) {
  Measurement z;
  z.position = model_.position(t);
  z.orientation = model_.orientation(t);
  z.carrier_from = last_position_;
  z.carrier_to = z.position;
  z.carrier_rotation = (z.orientation * last_orientation_.conjugate()).normalized();
  z.speed = model_.velocity(t).norm();
  last_position_ = z.position;
  last_orientation_ = z.orientation;
  return z;
}

}  // namespace opf
