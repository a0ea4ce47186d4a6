#include "opf/permanence/axis_motion_model.h"

#include "opf/permanence/ballistic_motion.h"
#include "opf/permanence/constant_position_motion.h"
#include "opf/permanence/constant_velocity_motion.h"
#include "opf/permanence/damped_velocity_motion.h"

namespace opf {

std::string_view model_name(MotionModel model) {
  switch (model) {
    case MotionModel::kConstantPosition:
      return "constant_position";
    case MotionModel::kConstantVelocity:
      return "constant_velocity";
    case MotionModel::kDampedVelocity:
      return "damped_velocity";
    case MotionModel::kBallistic:
      return "ballistic";
  }
  return "unknown";
}

AxisMotionStep position_velocity_block(const kalman::LinearModel<3>& model) {
  AxisMotionStep step;
  step.transition = model.transition.topLeftCorner<2, 2>();
  step.process_noise = model.process_noise.topLeftCorner<2, 2>();
  return step;
}

AxisMotionStep AxisMotionModel::step(double dt) const {
  switch (model) {
    case MotionModel::kConstantPosition:
      return constant_position_motion(intensity, dt);
    case MotionModel::kConstantVelocity:
      return constant_velocity_motion(intensity, dt);
    case MotionModel::kDampedVelocity:
      return damped_velocity_motion(intensity, time_constant, dt);
    case MotionModel::kBallistic:
      return ballistic_motion(intensity, acceleration, dt);
  }
  return {};
}

}  // namespace opf
