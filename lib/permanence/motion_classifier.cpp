#include "opf/permanence/motion_classifier.h"

#include "opf/core/so3.h"

namespace opf {

Motion classify_motion(std::span<const TrajectorySample> window,
                       const MotionThresholds& thresholds) {
  const double t2 = thresholds.translation * thresholds.translation;
  for (std::size_t p = 0; p < window.size(); ++p) {
    for (std::size_t q = p + 1; q < window.size(); ++q) {
      if ((window[p].position - window[q].position).squaredNorm() > t2) return Motion::kMoving;
      if (so3::angle_between(window[p].orientation, window[q].orientation) > thresholds.rotation)
        return Motion::kMoving;
    }
  }
  return Motion::kStatic;
}

Motion classify_fitted_motion(const TrajectoryModel& model, double t_first, double t_last,
                              const MotionThresholds& thresholds) {
  if ((model.position(t_last) - model.position(t_first)).norm() > thresholds.translation)
    return Motion::kMoving;
  if (so3::angle_between(model.orientation(t_first), model.orientation(t_last)) >
      thresholds.rotation)
    return Motion::kMoving;
  return Motion::kStatic;
}

}  // namespace opf
