#include "opf/permanence/axis_motion_model.h"

#include "opf/permanence/ballistic_motion.h"
#include "opf/permanence/constant_position_motion.h"
#include "opf/permanence/constant_velocity_motion.h"
#include "opf/permanence/damped_velocity_motion.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace opf {
namespace {

void expect_same(const AxisMotionStep& a, const AxisMotionStep& b) {
  EXPECT_EQ(a.transition, b.transition);
  EXPECT_EQ(a.process_noise, b.process_noise);
  EXPECT_EQ(a.offset, b.offset);
}

// Each model with its parameters steps as its own discretisation, with only its parameters.
TEST(AxisMotionModel, StepsAsItsModel) {
  const double dt = 0.05;
  expect_same(AxisMotionModel{MotionModel::kConstantPosition, 0.2, 7.0, 5.0}.step(dt),
              constant_position_motion(0.2, dt));
  expect_same(AxisMotionModel{MotionModel::kConstantVelocity, 0.2, 7.0, 5.0}.step(dt),
              constant_velocity_motion(0.2, dt));
  expect_same(AxisMotionModel{MotionModel::kDampedVelocity, 0.2, 7.0, 5.0}.step(dt),
              damped_velocity_motion(0.2, 7.0, dt));
  expect_same(AxisMotionModel{MotionModel::kBallistic, 0.2, 7.0, 5.0}.step(dt),
              ballistic_motion(0.2, 5.0, dt));
}

TEST(AxisMotionModel, NamesEveryModelApart) {
  std::set<std::string> names;
  for (int m = 0; m < kMotionModelCount; ++m)
    names.emplace(model_name(static_cast<MotionModel>(m)));
  EXPECT_EQ(names, (std::set<std::string>{"constant_position", "constant_velocity",
                                          "damped_velocity", "ballistic"}));
}

}  // namespace
}  // namespace opf
