#include "opf/permanence/constant_velocity_motion.h"

namespace opf {

AxisMotionStep constant_velocity_motion(double q, double dt) {
  // The Kalman core's per-axis discretisation over (p, v, a), restricted to (p, v).
  const kalman::LinearModel<3> model = kalman::constant_velocity_model(q, dt);
  AxisMotionStep step;
  step.transition = model.transition.topLeftCorner<2, 2>();
  step.process_noise = model.process_noise.topLeftCorner<2, 2>();
  return step;
}

}  // namespace opf
