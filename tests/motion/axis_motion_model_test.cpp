#include "opf/motion/axis_motion_model.h"

#include "opf/motion/ballistic_motion.h"
#include "opf/motion/constant_position_motion.h"
#include "opf/motion/constant_velocity_motion.h"
#include "opf/motion/damped_velocity_motion.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

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

// A list's steps are each model's own, to the bit: the damped members at one time constant share
// their exponentials, also past the eight time constants kept (the rest step alone).
TEST(AxisMotionModel, StepsOverAListAreEachModelsOwnStep) {
  std::vector<AxisMotionModel> models = {{MotionModel::kConstantPosition, 0.01, 1.0, 0.0},
                                         {MotionModel::kConstantVelocity, 0.3, 1.0, 0.0},
                                         {MotionModel::kBallistic, 3.0, 1.0, -9.81}};
  for (int k = 0; k < 10; ++k)
    for (const double q : {0.03, 0.3, 3.0})
      models.push_back({MotionModel::kDampedVelocity, q, 0.1 * (k + 1), 0.0});
  models.push_back({MotionModel::kDampedVelocity, 7.0, 0.3, 0.0});  // a time constant met before
  for (const double dt : {1.0 / 30.0, 0.0331, 1e-4, 2.5}) {
    std::vector<AxisMotionStep> steps(3);  // resized
    steps_over(models, dt, steps);
    ASSERT_EQ(steps.size(), models.size());
    for (std::size_t j = 0; j < models.size(); ++j) {
      SCOPED_TRACE(j);
      expect_same(steps[j], models[j].step(dt));
    }
  }
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
