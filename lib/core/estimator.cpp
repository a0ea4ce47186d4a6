#include "opf/core/estimator.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace opf {

double time_step(std::string_view estimator, double previous, double t) {
  const double dt = t - previous;
  if (!(dt > 0.0)) {
    std::ostringstream msg;
    msg << estimator << ": time " << t << " s does not follow the previous time " << previous
        << " s";
    throw std::invalid_argument(msg.str());
  }
  return dt;
}

double stated_extra_noise(const EnsembleView& view, const mrpt::poses::CPose3D* measurement) {
  for (const Detection& detection : view.frame.detections)
    if (&detection.pose == measurement) return detection.extra_noise;
  return 0.0;
}

double stated_radius(const EnsembleView& view, std::string_view object) {
  for (const StatedRadius& r : view.stated_radii)
    if (r.object == object) return r.radius;
  return 0.0;
}

Eigen::Vector3d stated_box(const EnsembleView& view, std::string_view object) {
  for (const StatedRadius& r : view.stated_radii)
    if (r.object == object) return r.box;
  return Eigen::Vector3d::Zero();
}

double observation_sigma(double configured, double extra_noise) {
  return std::hypot(configured, extra_noise);
}

}  // namespace opf
