#include "opf/control/cautious_tracking_controller.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opf {
namespace {

TEST(CautiousTrackingController, GainFollowsTheSigmoidOfTheUncertainty) {
  CautiousControllerOptions options;  // eps = 0.1, n = 4
  EXPECT_DOUBLE_EQ(cautious_gain(2.0, 0.0, options), 2.0);
  EXPECT_DOUBLE_EQ(cautious_gain(2.0, 0.05, options), 1.0);  // half at eps / 2
  const double u = 0.03;
  const double half_eps_n = std::pow(0.05, 4);
  EXPECT_NEAR(cautious_gain(2.0, u, options), 2.0 * half_eps_n / (half_eps_n + std::pow(u, 4)),
              1e-15);
}

TEST(CautiousTrackingController, GainsFallToZeroAsUncertaintyReachesEpsilonSafe) {
  CautiousControllerOptions options;
  double previous = cautious_gain(1.0, 0.0, options);
  for (double u = 0.005; u < options.epsilon_safe; u += 0.005) {
    const double k = cautious_gain(1.0, u, options);
    EXPECT_LT(k, previous) << u;  // strictly decreasing
    previous = k;
  }
  // Just below eps the sigmoid leaves k_nom / (1 + 2^n) = 1/17; at eps the robot stops.
  EXPECT_NEAR(cautious_gain(1.0, 0.1 - 1e-12, options), 1.0 / 17.0, 1e-9);
  EXPECT_EQ(cautious_gain(1.0, 0.1, options), 0.0);
  options.stop_at_epsilon_safe = false;
  EXPECT_NEAR(cautious_gain(1.0, 0.1, options), 1.0 / 17.0, 1e-12);
  // A steeper sigmoid brings the gain at eps closer to zero.
  options.steepness = 20.0;
  EXPECT_LT(cautious_gain(1.0, 0.1, options), 1e-6);
}

TEST(CautiousTrackingController, CommandIsProportionalPlusFeedforward) {
  CautiousControllerOptions options;
  const Eigen::Vector3d robot(0.5, 0.2, 0.4), object(0.55, 0.1, 0.0), velocity(0, -0.1, 0);
  const Eigen::Vector3d command = cautious_velocity_command(robot, object, velocity, 0.0, options);
  EXPECT_LT((command - (-2.0 * (robot - object) + 1.0 * velocity)).norm(), 1e-15);
  EXPECT_EQ(cautious_velocity_command(robot, object, velocity, 0.2, options),
            Eigen::Vector3d::Zero());
}

TEST(CautiousTrackingController, RejectsBadOptions) {
  CautiousControllerOptions options;
  options.kd_nominal = 1.5;
  EXPECT_THROW(validate(options), std::invalid_argument);
  options = {};
  options.steepness = 0.5;
  EXPECT_THROW(validate(options), std::invalid_argument);
}

}  // namespace
}  // namespace opf
