#include "py_estimate.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/recovery_events.h"

#include <Eigen/Geometry>

namespace opf::python {

PyEstimate to_python(const Estimate& estimate, double epsilon_safe) {
  PyEstimate p;
  p.object = estimate.object;
  p.t = estimate.t;
  p.position = translation_of(estimate.pose.mean);
  Eigen::Quaterniond q = orientation_of(estimate.pose.mean);
  // One sign of q as in estimate files; adding 0.0 turns -0 into 0 as the file's writer does.
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  p.quaternion = q.coeffs();  // Eigen stores x, y, z, w
  p.quaternion(3) += 0.0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) p.covariance(i, j) = estimate.pose.cov(i, j);
  p.trace = estimate.observation_trace;
  p.mode = mode_column(estimate.mode, estimate.recovery);
  p.hypothesis = estimate.hypothesis;
  p.probability = estimate.probability;
  p.alert = safety_alert(estimate, epsilon_safe);
  p.model = estimate.motion_model;
  return p;
}

}  // namespace opf::python
