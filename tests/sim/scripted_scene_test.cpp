#include "opf/sim/scripted_scene.h"

#include "opf/core/so3.h"

#include <gtest/gtest.h>

namespace opf::sim {
namespace {

ScriptedBody body(const std::string& name, std::vector<Waypoint> waypoints,
                  std::vector<CarriedSpan> carried = {}, bool rolling = false) {
  ScriptedBody b;
  b.body.name = name;
  b.body.size = Eigen::Vector3d(0.025, 0.025, 0.025);
  b.waypoints = std::move(waypoints);
  b.carried = std::move(carried);
  b.rolling = rolling;
  return b;
}

TEST(ScriptedScene, WaypointsInterpolateLinearlyAndHoldAtTheEnds) {
  const ScriptedScene scene(
      {body("mug", {{1.0, {0.4, 0.15, 0.03}, {}}, {3.0, {0.4, -0.05, 0.03}, {}}})});
  EXPECT_EQ(scene.pose_of("mug", 0.0).position, Eigen::Vector3d(0.4, 0.15, 0.03));
  EXPECT_LT((scene.pose_of("mug", 2.0).position - Eigen::Vector3d(0.4, 0.05, 0.03)).norm(), 1e-15);
  EXPECT_EQ(scene.pose_of("mug", 9.0).position, Eigen::Vector3d(0.4, -0.05, 0.03));
}

TEST(ScriptedScene, OrientationSlerpsBetweenWaypoints) {
  const Eigen::Quaterniond turned = so3::exp(Eigen::Vector3d(0, 0, 1.0));
  const ScriptedScene scene(
      {body("cup", {{0.0, {0, 0, 0}, Eigen::Quaterniond::Identity()}, {2.0, {0, 0, 0}, turned}})});
  EXPECT_NEAR(so3::angle_between(scene.pose_of("cup", 1.0).orientation,
                                 so3::exp(Eigen::Vector3d(0, 0, 0.5))),
              0.0, 1e-12);
}

TEST(ScriptedScene, CarriedBodyKeepsItsOffsetAndStaysWhereLeft) {
  // The mug moves from (0.4, 0.06) to (0.8, 0.15) between t = 2 and 4 carrying the ball, which
  // sits 3 cm below the mug's centre; after the carry the ball rests where the mug left it, then
  // rolls on to its next waypoint. Waypoints interpolate linearly across a carry, so a body that
  // rests until it is picked up has a waypoint at the carry's start.
  const ScriptedScene scene({body("mug", {{2.0, {0.4, 0.06, 0.03}, {}},
                                          {4.0, {0.8, 0.15, 0.03}, {}},
                                          {5.0, {0.8, 0.3, 0.03}, {}}}),
                             body("ball",
                                  {{0.0, {0.4, 0.06, 0.0}, {}},
                                   {2.0, {0.4, 0.06, 0.0}, {}},
                                   {7.0, {0.8, 0.15, 0.0}, {}},
                                   {8.0, {0.3, -0.35, 0.0}, {}}},
                                  {{2.0, 4.5, "mug"}})});
  EXPECT_LT((scene.pose_of("ball", 3.0).position - Eigen::Vector3d(0.6, 0.105, 0.0)).norm(), 1e-12);
  // The carry lasts until 4.5: the ball follows the mug's next leg until then.
  EXPECT_LT((scene.pose_of("ball", 4.25).position - Eigen::Vector3d(0.8, 0.1875, 0.0)).norm(),
            1e-12);
  // From 4.5 it stays at (0.8, 0.225) until it heads for (0.8, 0.15) at 7.0, then on.
  EXPECT_LT((scene.pose_of("ball", 5.0).position - Eigen::Vector3d(0.8, 0.21, 0.0)).norm(), 1e-12);
  EXPECT_LT((scene.pose_of("ball", 7.5).position - Eigen::Vector3d(0.55, -0.1, 0.0)).norm(), 1e-12);
}

TEST(ScriptedScene, CarrierRotationTurnsTheCarriedBody) {
  const Eigen::Quaterniond quarter = so3::exp(Eigen::Vector3d(0, 0, M_PI / 2));
  const ScriptedScene scene(
      {body("hand", {{0.0, {0, 0, 0}, Eigen::Quaterniond::Identity()}, {1.0, {0, 0, 0}, quarter}}),
       body("cube", {{0.0, {0.1, 0, 0}, {}}}, {{0.0, 2.0, "hand"}})});
  const BodyPose p = scene.pose_of("cube", 1.0);
  EXPECT_LT((p.position - Eigen::Vector3d(0, 0.1, 0)).norm(), 1e-12);
  EXPECT_NEAR(so3::angle_between(p.orientation, quarter), 0.0, 1e-12);
}

TEST(ScriptedScene, RollingBallTurnsByDistanceOverRadius) {
  // 0.1 m along x with radius 0.025: 4 rad about z x x = +y.
  const ScriptedScene scene(
      {body("ball", {{0.0, {0, 0, 0}, {}}, {1.0, {0.1, 0, 0}, {}}}, {}, true)});
  const BodyPose half = scene.pose_of("ball", 0.5);
  EXPECT_LT((so3::log(half.orientation) - Eigen::Vector3d(0, 2.0, 0)).norm(), 1e-12);
  EXPECT_NEAR(so3::angle_between(scene.pose_of("ball", 1.0).orientation,
                                 so3::exp(Eigen::Vector3d(0, 4.0, 0))),
              0.0, 1e-12);
}

TEST(ScriptedScene, AFlightIsAParabolaWithSpin) {
  ScriptedBody b = body("ball", {{0.0, {0, 0, 1}, {}}});
  b.flight = ScriptedBody::Flight{
      0.0, 1.0, {0, 0, 1}, {2, 0, 3}, {0, 4, 0}, Eigen::Quaterniond::Identity(), 9.81};
  const ScriptedScene scene({b});
  const BodyPose p = scene.pose_of("ball", 0.5);
  EXPECT_LT((p.position - Eigen::Vector3d(1.0, 0.0, 1.0 + 1.5 - 0.5 * 9.81 * 0.25)).norm(), 1e-12);
  EXPECT_NEAR(so3::angle_between(p.orientation, so3::exp(Eigen::Vector3d(0, 2.0, 0))), 0.0, 1e-12);
  // After the flight the waypoints apply again.
  EXPECT_EQ(scene.pose_of("ball", 2.0).position, Eigen::Vector3d(0, 0, 1));
}

TEST(ScriptedScene, DrivenBodyFollowsItsDriver) {
  ScriptedScene scene({body("hand", {{0.0, {0.5, 0, 0.4}, {}}})});
  scene.drive("hand", {Eigen::Vector3d(0.55, 0.2, 0.3), Eigen::Quaterniond::Identity()});
  EXPECT_EQ(scene.pose_of("hand", 3.0).position, Eigen::Vector3d(0.55, 0.2, 0.3));
  EXPECT_EQ(scene.at(3.0).poses[0].position, Eigen::Vector3d(0.55, 0.2, 0.3));
}

TEST(ScriptedScene, RejectsBadScripts) {
  EXPECT_THROW(ScriptedScene({body("a", {})}), std::invalid_argument);
  EXPECT_THROW(ScriptedScene({body("a", {{1.0, {0, 0, 0}, {}}, {1.0, {1, 0, 0}, {}}})}),
               std::invalid_argument);
  EXPECT_THROW(ScriptedScene({body("a", {{0.0, {0, 0, 0}, {}}}, {{0.0, 1.0, "nobody"}})}),
               std::invalid_argument);
  EXPECT_THROW(ScriptedScene({body("a", {{0.0, {0, 0, 0}, {}}}, {{0.0, 1.0, "b"}}),
                              body("b", {{0.0, {0, 0, 0}, {}}}, {{0.0, 1.0, "a"}})}),
               std::invalid_argument);
}

}  // namespace
}  // namespace opf::sim
