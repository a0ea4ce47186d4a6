#include "opf/motion/damped_velocity_motion.h"

#include "opf/motion/constant_velocity_motion.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

// q = 2 m/s^2/sqrt(Hz), T = 0.5 s, dt = 0.2 s (x = 0.4): the closed forms evaluated at 30 digits
// (and checked against the integral of Phi(s) G G^T Phi(s)^T q^2 over [0, dt] by quadrature).
TEST(DampedVelocityMotion, MatchesTheHandComputedDiscretisation) {
  const AxisMotionStep step = damped_velocity_motion(2.0, 0.5, 0.2);
  EXPECT_DOUBLE_EQ(step.transition(0, 0), 1.0);
  EXPECT_NEAR(step.transition(0, 1), 0.164839976982180349627783537426, 1e-15);
  EXPECT_DOUBLE_EQ(step.transition(1, 0), 0.0);
  EXPECT_NEAR(step.transition(1, 1), 0.670320046035639300744432925148, 1e-15);
  EXPECT_NEAR(step.process_noise(0, 0), 0.007987805006333902886907328894, 1e-15);
  EXPECT_NEAR(step.process_noise(0, 1), 0.0543444360229714949706182673599, 1e-15);
  EXPECT_NEAR(step.process_noise(1, 0), 0.0543444360229714949706182673599, 1e-15);
  EXPECT_NEAR(step.process_noise(1, 1), 0.550671035882778408569897614984, 1e-15);
  EXPECT_EQ(step.offset, kalman::Vector<2>::Zero());
}

// The same at dt = 0.002 s (x = 0.004), where the position variance is summed as its series:
// to 1e-12 of its value.
TEST(DampedVelocityMotion, MatchesTheHandComputedSeriesForAShortStep) {
  const AxisMotionStep step = damped_velocity_motion(2.0, 0.5, 0.002);
  EXPECT_NEAR(step.transition(0, 1), 0.001996005328004263823846806710261216541737, 1e-17);
  EXPECT_NEAR(step.transition(1, 1), 0.9960079893439914723523063865794775669165, 1e-15);
  EXPECT_NEAR(step.process_noise(0, 0) / 1.063472631476733896151225965458068642933e-8, 1.0, 1e-12);
  EXPECT_NEAR(step.process_noise(0, 1) / 7.968074538842817628463554958257755151418e-6, 1.0, 1e-12);
  EXPECT_NEAR(step.process_noise(1, 1) / 0.007968085162939369660130299731128350656639, 1.0, 1e-12);
}

// Exact: two steps of dt are one of 2 dt; at T = 0.3 s, dt = 0.0015 s steps by the series
// (x = 0.005) and 2 dt by the closed form (x = 0.01), dt = 0.2 s both by the closed form.
TEST(DampedVelocityMotion, TwoHalfStepsAreOneStep) {
  for (const double dt : {0.0015, 0.2}) {
    const AxisMotionStep half = damped_velocity_motion(1.5, 0.3, dt);
    const AxisMotionStep whole = damped_velocity_motion(1.5, 0.3, 2.0 * dt);
    const kalman::Matrix<2> composed =
        half.transition * half.process_noise * half.transition.transpose() + half.process_noise;
    EXPECT_TRUE((half.transition * half.transition).isApprox(whole.transition, 1e-13)) << dt;
    EXPECT_TRUE(composed.isApprox(whole.process_noise, 1e-10)) << dt << "\n" << composed;
  }
}

// T -> infinity: the velocity is never forgotten, constant velocity at the same q; the position
// variance (where the closed form would cancel) to 1e-9 of the model's own.
TEST(DampedVelocityMotion, TendsToConstantVelocityForALongTimeConstant) {
  const AxisMotionStep cv = constant_velocity_motion(0.7, 1.0 / 30.0);
  for (const double time_constant : {1e3, 1e6, 1e12}) {
    const AxisMotionStep step = damped_velocity_motion(0.7, time_constant, 1.0 / 30.0);
    const double tolerance = 1e-9 + 1.0 / (30.0 * time_constant);  // first order in dt / T
    EXPECT_TRUE(step.transition.isApprox(cv.transition, tolerance)) << time_constant;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        EXPECT_NEAR(step.process_noise(i, j) / cv.process_noise(i, j), 1.0, tolerance)
            << time_constant << " " << i << j;
  }
}

// T -> 0: the velocity is forgotten at once (F -> [1 0; 0 0]) and the noise vanishes: the
// position random-walks with the velocity density q T, so a still object.
TEST(DampedVelocityMotion, TendsToAStillObjectForAShortTimeConstant) {
  const double q = 3.0, dt = 0.1;
  for (const double time_constant : {1e-3, 1e-6}) {
    const AxisMotionStep step = damped_velocity_motion(q, time_constant, dt);
    EXPECT_NEAR(step.transition(0, 1), time_constant, 1e-15);
    EXPECT_NEAR(step.transition(1, 1), 0.0, 1e-15);
    const double walk = q * q * time_constant * time_constant * dt;  // (q T)^2 dt
    EXPECT_NEAR(step.process_noise(0, 0) / walk, 1.0, 3.0 * time_constant / dt);
    EXPECT_NEAR(step.process_noise(1, 1), q * q * time_constant / 2.0, 1e-15);
    EXPECT_LT(step.process_noise.norm(), 10.0 * time_constant);
  }
}

}  // namespace
}  // namespace opf
