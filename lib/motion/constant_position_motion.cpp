#include "opf/motion/constant_position_motion.h"

namespace opf {

AxisMotionStep constant_position_motion(double q, double dt) {
  return position_velocity_block(kalman::constant_position_model(q, dt));
}

}  // namespace opf
