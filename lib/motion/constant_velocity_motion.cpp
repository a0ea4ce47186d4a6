#include "opf/motion/constant_velocity_motion.h"

namespace opf {

AxisMotionStep constant_velocity_motion(double q, double dt) {
  return position_velocity_block(kalman::constant_velocity_model(q, dt));
}

}  // namespace opf
