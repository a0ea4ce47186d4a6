#include "opf/motion/constant_position_motion.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

// q = 0.5 m/s/sqrt(Hz) over dt = 0.1 s: the position's variance grows by q^2 dt = 0.025 m^2; the
// velocity is pinned at 0 (F's second row and Q's second row and column zero).
TEST(ConstantPositionMotion, IsARandomWalkWithThePinnedVelocity) {
  const AxisMotionStep step = constant_position_motion(0.5, 0.1);
  kalman::Matrix<2> f;
  f << 1.0, 0.0, 0.0, 0.0;
  kalman::Matrix<2> q;
  q << 0.025, 0.0, 0.0, 0.0;
  EXPECT_TRUE(step.transition.isApprox(f, 1e-15)) << step.transition;
  EXPECT_NEAR((step.process_noise - q).cwiseAbs().maxCoeff(), 0.0, 1e-15) << step.process_noise;
  EXPECT_EQ(step.offset, kalman::Vector<2>::Zero());
}

}  // namespace
}  // namespace opf
