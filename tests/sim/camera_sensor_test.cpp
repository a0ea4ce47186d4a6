#include "opf/sim/camera_sensor.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opf::sim {
namespace {

// Each test makes its own sensor: MRPT allows one off-screen renderer per process at a time, and
// ctest runs every test case in a process of its own.
SceneSnapshot ball_and_box(const Eigen::Vector3d& box_position, double box_height = 0.1) {
  SceneSnapshot s;
  Body table{"table", Shape::kBox, {1.2, 1.4, 0.02}, palette::kTable, false};
  Body ball{"ball", Shape::kSphere, {0.025, 0.025, 0.025}, palette::kBall, true};
  Body box{"box", Shape::kBox, {0.12, 0.12, box_height}, palette::kTray, true};
  s.bodies = {table, ball, box};
  s.poses = {BodyPose{{0.55, 0.0, -0.035}, Eigen::Quaterniond::Identity()},
             BodyPose{{0.45, 0.05, 0.0}, Eigen::Quaterniond::Identity()},
             BodyPose{box_position, Eigen::Quaterniond::Identity()}};
  return s;
}

const CameraModel kCamera = CameraModel::top_down({0.55, 0.0, 0.49});

TEST(CameraSensor, MeasuresAFullyVisibleBallsCentre) {
  CameraSensor sensor(kCamera);
  // A flat (1 cm) box off the optical axis: its sides hardly show.
  const CameraFrame frame = sensor.observe(ball_and_box({0.7, -0.2, 0.05}, 0.01));
  ASSERT_EQ(frame.sightings.size(), 2u);  // the table is not tracked
  const Sighting& ball = frame.sightings[0];
  EXPECT_EQ(ball.object, "ball");
  ASSERT_TRUE(ball.detected);
  // The whole silhouette is seen (the tessellated sphere's is 0.3% smaller than the true one).
  EXPECT_NEAR(ball.visible_fraction, 1.0, 0.02);
  // The median-depth surface point pushed back by r / sqrt(2) lands on the centre to within the
  // depth image's quantisation and the tessellation's flattening: 2 mm at 0.49 m.
  EXPECT_LT((ball.position - Eigen::Vector3d(0.45, 0.05, 0.0)).norm(), 0.002);
  const Sighting& box = frame.sightings[1];
  ASSERT_TRUE(box.detected);
  EXPECT_LT((box.position - Eigen::Vector3d(0.7, -0.2, 0.05)).norm(), 0.002);
}

// A known limitation, measured: off the optical axis a tall body shows its sides, which pull the
// blob's centroid away from the axis, so its measured centre is biased outwards. Here a 10 cm
// box 0.25 m off-axis, 0.44 m below the camera, shows a side ~h * 0.25 / 0.44 = 5.7 cm deep
// beside its 12 cm top: a third of the blob, whose centroid moves out by about a third of
// (6 + 2.8) cm, i.e. ~1-3 cm after back-projection. Measured: 1.3 cm.
TEST(CameraSensor, ATallBodyOffAxisIsBiasedOutwards) {
  CameraSensor sensor(kCamera);
  const Eigen::Vector3d truth(0.7, -0.2, 0.05);
  const Sighting box = sensor.observe(ball_and_box(truth)).sightings[1];
  ASSERT_TRUE(box.detected);
  const Eigen::Vector2d outward = (truth - kCamera.position()).head<2>().normalized();
  const double bias = (box.position - truth).head<2>().dot(outward);
  EXPECT_GT(bias, 0.005);
  EXPECT_LT(bias, 0.03);
}

TEST(CameraSensor, ACoveredBallIsNotDetected) {
  CameraSensor sensor(kCamera);
  // The box sits right over the ball, between it and the camera.
  const CameraFrame frame = sensor.observe(ball_and_box({0.45, 0.05, 0.1}));
  EXPECT_FALSE(frame.sightings[0].detected);
  EXPECT_EQ(frame.sightings[0].visible_fraction, 0.0);
}

TEST(CameraSensor, AHalfCoveredBallIsSeenInPartWithABiasedCentre) {
  CameraSensor sensor(kCamera);
  // The box's edge (x from 0.39 to 0.51, y from 0.05 - 0.06 = -0.01 up) covers the ball's
  // +y half in the image: the visible part lies towards -y, and so does the centroid.
  const CameraFrame frame = sensor.observe(ball_and_box({0.45, 0.11, 0.1}));
  const Sighting& ball = frame.sightings[0];
  ASSERT_TRUE(ball.detected);
  EXPECT_GT(ball.visible_fraction, 0.2);
  EXPECT_LT(ball.visible_fraction, 0.8);
  EXPECT_LT(ball.position.y(), 0.05 - 0.005);
  // The partial view's stated bound holds the bias the renderer and detector produced.
  const double bias = (ball.position - Eigen::Vector3d(0.45, 0.05, 0.0)).head<2>().norm();
  EXPECT_GT(ball.partial_view_offset, bias);
  EXPECT_LT(ball.partial_view_offset, 0.025);  // at most the radius
  // The radius stated is the whole silhouette's, however much of it is covered.
  EXPECT_NEAR(ball.radius, 0.025, 5e-4);
}

TEST(CameraSensor, AWholeViewStatesNoPartialViewOffset) {
  CameraSensor sensor(kCamera);
  const Sighting ball = sensor.observe(ball_and_box({0.7, -0.2, 0.05}, 0.01)).sightings[0];
  ASSERT_TRUE(ball.detected);
  // 1 - f is the tessellation's 0.3% and the pixels' rounding: below a tenth of a millimetre.
  EXPECT_LT(ball.partial_view_offset, 1e-4);
  // Its silhouette's radius is the sphere's 2.5 cm, within the pixels' rounding (0.5 mm, 2%).
  EXPECT_NEAR(ball.radius, 0.025, 5e-4);
}

// A box body's detections state its box, its own size; other shapes state none.
TEST(CameraSensor, ABoxStatesItsSizeAndABallNone) {
  CameraSensor sensor(kCamera);
  const CameraFrame frame = sensor.observe(ball_and_box({0.7, -0.2, 0.05}, 0.01));
  ASSERT_TRUE(frame.sightings[0].detected && frame.sightings[1].detected);
  EXPECT_EQ(frame.sightings[0].box, Eigen::Vector3d::Zero());
  EXPECT_EQ(frame.sightings[1].box, Eigen::Vector3d(0.12, 0.12, 0.01));
}

TEST(CameraSensor, ABallHalfOutOfTheFrameIsSeenInPartWithItsWholeSize) {
  CameraSensor sensor(kCamera);
  // The ball's centre on the image's right edge (column width - 0.5): the frame's edge covers
  // half of it as a cover's would, and the detector knows its blob ends at the edge.
  const double edge_y =
      kCamera.back_project(Eigen::Vector2d(kCamera.width - 0.5, kCamera.cy), 0.49).y();
  SceneSnapshot s = ball_and_box({0.45, -0.2, 0.05}, 0.01);
  s.poses[1].position = {0.55, edge_y, 0.0};
  const Sighting ball = sensor.observe(s).sightings[0];
  ASSERT_TRUE(ball.detected);
  EXPECT_GT(ball.visible_fraction, 0.35);
  EXPECT_LT(ball.visible_fraction, 0.65);
  // The centroid lies inside the frame (nearer its centre line y = 0), and the stated
  // partial-view offset bounds the bias.
  const double bias = (ball.position - s.poses[1].position).head<2>().norm();
  EXPECT_LT(std::abs(ball.position.y()), std::abs(edge_y) - 0.005);
  EXPECT_GT(ball.partial_view_offset, bias);
  EXPECT_LT(ball.partial_view_offset, ball.radius);
  // The size stated is the whole silhouette's: this far off the axis the sphere's is an ellipse
  // stretched outwards, of the area of a 3.0 cm disc; the half in the frame alone would state
  // 3.0 / sqrt(2) = 2.1 cm, less than the ball's 2.5 cm.
  EXPECT_GT(ball.radius, 0.025);
  EXPECT_LT(ball.radius, 0.032);
}

TEST(PartialViewOffset, IsTheCoveredShareOfTheEquivalentDiscsRadius) {
  // A silhouette of pi 50^2 pixels at 0.5 m has rho = 50 px = 50 * 0.5 / f metres.
  const double area = M_PI * 50.0 * 50.0;
  const double rho = 50.0 * 0.5 / std::sqrt(kCamera.fx * kCamera.fy);
  EXPECT_NEAR(partial_view_offset(0.5, area, 0.5, kCamera), 0.5 * rho, 1e-15);
  EXPECT_NEAR(partial_view_offset(0.2, area, 0.5, kCamera), 0.8 * rho, 1e-15);
  EXPECT_EQ(partial_view_offset(1.0, area, 0.5, kCamera), 0.0);
  EXPECT_EQ(partial_view_offset(0.5, 0.0, 0.5, kCamera), 0.0);  // nothing expected: nothing stated
}

TEST(SilhouetteRadius, IsTheEquivalentDiscsRadiusInMetresAtItsDepth) {
  const double area = M_PI * 50.0 * 50.0;
  EXPECT_NEAR(silhouette_radius(area, 0.5, kCamera),
              50.0 * 0.5 / std::sqrt(kCamera.fx * kCamera.fy), 1e-15);
  EXPECT_EQ(silhouette_radius(0.0, 0.5, kCamera), 0.0);
}

TEST(PartialViewOffset, BoundsTheCentroidOfADiscCutByAStraightEdge) {
  // The unit disc's part x <= c: area A = c sqrt(1 - c^2) + asin c + pi / 2, first moment
  // -(2/3) (1 - c^2)^(3/2); its centroid lies (2/3) (1 - c^2)^(3/2) / A off the centre, within
  // (1 - f) of it for the visible share f = A / pi, from a sliver to almost all of it.
  const auto area = [](double c) { return c * std::sqrt(1.0 - c * c) + std::asin(c) + M_PI / 2.0; };
  const auto offset = [&](double c) { return (2.0 / 3.0) * std::pow(1.0 - c * c, 1.5) / area(c); };
  // The closed forms against the half disc's known centroid, 4 rho / (3 pi).
  EXPECT_NEAR(area(0.0), M_PI / 2.0, 1e-15);
  EXPECT_NEAR(offset(0.0), 4.0 / (3.0 * M_PI), 1e-15);
  for (double c = -0.999; c < 1.0; c += 0.001)
    EXPECT_LE(offset(c), 1.0 - area(c) / M_PI) << "edge at " << c;
}

}  // namespace
}  // namespace opf::sim
