#include "opf/motion/constant_velocity_motion.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

// q = 2 m/s^2/sqrt(Hz) over dt = 0.1 s: Q = 4 [0.001/3 0.005; 0.005 0.1].
TEST(ConstantVelocityMotion, IsTheWhiteNoiseAccelerationModel) {
  const AxisMotionStep step = constant_velocity_motion(2.0, 0.1);
  kalman::Matrix<2> f;
  f << 1.0, 0.1, 0.0, 1.0;
  kalman::Matrix<2> q;
  q << 4.0 * 0.001 / 3.0, 0.02, 0.02, 0.4;
  EXPECT_NEAR((step.transition - f).cwiseAbs().maxCoeff(), 0.0, 1e-15) << step.transition;
  EXPECT_NEAR((step.process_noise - q).cwiseAbs().maxCoeff(), 0.0, 1e-15) << step.process_noise;
  EXPECT_EQ(step.offset, kalman::Vector<2>::Zero());
}

// Exact discretisation: two steps of dt are one of 2 dt (F F^T-propagated Q added up).
TEST(ConstantVelocityMotion, TwoHalfStepsAreOneStep) {
  const AxisMotionStep half = constant_velocity_motion(1.5, 0.05);
  const AxisMotionStep whole = constant_velocity_motion(1.5, 0.1);
  const kalman::Matrix<2> composed =
      half.transition * half.process_noise * half.transition.transpose() + half.process_noise;
  EXPECT_TRUE((half.transition * half.transition).isApprox(whole.transition, 1e-14));
  EXPECT_TRUE(composed.isApprox(whole.process_noise, 1e-14)) << composed;
}

}  // namespace
}  // namespace opf
