#include "opf/motion/ballistic_motion.h"

#include "opf/motion/constant_velocity_motion.h"

namespace opf {

AxisMotionStep ballistic_motion(double q, double g, double dt) {
  AxisMotionStep step = constant_velocity_motion(q, dt);
  step.offset << g * dt * dt / 2.0, g * dt;
  return step;
}

}  // namespace opf
