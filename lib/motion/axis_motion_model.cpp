#include "opf/motion/axis_motion_model.h"

#include "opf/motion/ballistic_motion.h"
#include "opf/motion/constant_position_motion.h"
#include "opf/motion/constant_velocity_motion.h"
#include "opf/motion/damped_velocity_motion.h"

#include <array>

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

void steps_over(std::span<const AxisMotionModel> models, double dt,
                std::vector<AxisMotionStep>& out) {
  out.resize(models.size());
  std::array<DampedVelocityDecay, 8> decays;  // one per time constant met, the first 8 kept
  std::size_t met = 0;
  for (std::size_t j = 0; j < models.size(); ++j) {
    const AxisMotionModel& m = models[j];
    std::size_t k = 0;
    if (m.model == MotionModel::kDampedVelocity)
      while (k < met && decays[k].time_constant != m.time_constant) ++k;
    if (m.model != MotionModel::kDampedVelocity || k == decays.size()) {  // or past the kept
      out[j] = m.step(dt);
      continue;
    }
    if (k == met) decays[met++] = damped_velocity_decay(m.time_constant, dt);
    out[j] = damped_velocity_motion(m.intensity, decays[k]);
  }
}

}  // namespace opf
