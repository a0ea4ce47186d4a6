#include "opf/motion/ballistic_motion.h"

#include "opf/motion/constant_velocity_motion.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

// g = -9.81 m/s^2 over dt = 0.1 s: b = (-0.04905 m, -0.981 m/s); F and Q are constant velocity's.
TEST(BallisticMotion, AddsTheKnownAccelerationsTerm) {
  const AxisMotionStep step = ballistic_motion(0.4, -9.81, 0.1);
  const AxisMotionStep cv = constant_velocity_motion(0.4, 0.1);
  EXPECT_NEAR(step.offset[0], -0.04905, 1e-15);
  EXPECT_NEAR(step.offset[1], -0.981, 1e-15);
  EXPECT_EQ(step.transition, cv.transition);
  EXPECT_EQ(step.process_noise, cv.process_noise);
}

// The noise-free flight: 30 steps of 1/30 s from (p, v) = (1 m, 3 m/s) land where p + v t + g t^2
// / 2 puts it after 1 s (2.5 - 4.905 / 1 ... = -0.905 m), at v + g t = -6.81 m/s.
TEST(BallisticMotion, StepsAlongTheParabola) {
  kalman::Vector<2> x(1.0, 3.0);
  const AxisMotionStep step = ballistic_motion(0.0, -9.81, 1.0 / 30.0);
  for (int k = 0; k < 30; ++k) x = step.transition * x + step.offset;
  EXPECT_NEAR(x[0], 1.0 + 3.0 - 9.81 / 2.0, 1e-12);
  EXPECT_NEAR(x[1], 3.0 - 9.81, 1e-12);
}

}  // namespace
}  // namespace opf
