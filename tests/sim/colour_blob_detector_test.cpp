#include "opf/sim/colour_blob_detector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "opf/sim/scene_renderer.h"
#include "opf/sim/silhouette.h"

namespace opf::sim {
namespace {

const Eigen::Vector3d kEye(0.55, 0.0, 0.49);  // paper experiment 1
constexpr double kBallRadius = 0.025;         // a 5 cm ball, the size the paper's scene suggests

Body ball(Colour colour = palette::kBall) {
  return make_body("ball", Shape::kSphere, Eigen::Vector3d::Constant(kBallRadius), colour);
}

Body mug(Colour colour) {
  return make_body("mug", Shape::kCylinder, Eigen::Vector3d(0.04, 0.04, 0.1), colour);
}

// A grey table whose top is the plane z = 0, and then the given bodies.
SceneSnapshot table_scene() {
  SceneSnapshot scene;
  scene.bodies.push_back(
      make_body("table", Shape::kBox, Eigen::Vector3d(1.2, 1.2, 0.04), palette::kTable, false));
  scene.poses.push_back(pose_at(Eigen::Vector3d(0.55, 0.0, -0.02)));
  return scene;
}

// Where a sphere's silhouette (an ellipse) is centred: its viewing cone, half-angle a around a
// direction t off the optical axis, spans f tan(t - a) to f tan(t + a) radially.
Eigen::Vector2d sphere_silhouette_centre(const Eigen::Vector3d& centre, double radius,
                                         const CameraModel& camera) {
  const Eigen::Vector3d c = camera.to_camera(centre);
  const double sin_t = std::hypot(c.x(), c.y()) / c.norm();
  const double cos_t = c.z() / c.norm();
  const double sin_a_sq = radius * radius / c.squaredNorm();
  const double offset = camera.fx * sin_t * cos_t / (cos_t * cos_t - sin_a_sq);
  const Eigen::Vector2d radial = Eigen::Vector2d(c.x(), c.y()).normalized();
  return Eigen::Vector2d(camera.cx, camera.cy) + offset * radial;
}

void add(SceneSnapshot& scene, const Body& body, const BodyPose& pose) {
  scene.bodies.push_back(body);
  scene.poses.push_back(pose);
}

class ColourBlobDetectorTest : public ::testing::Test {
 protected:
  // One context for the suite: MRPT allows only one at a time, and the first costs ~0.15 s.
  static void SetUpTestSuite() {
    renderer_ = std::make_unique<SceneRenderer>(CameraModel::top_down(kEye));
  }
  static void TearDownTestSuite() { renderer_.reset(); }

  const CameraModel& camera() const { return renderer_->camera(); }

  std::optional<BlobMeasurement> detect(const SceneSnapshot& scene, const Colour& colour) {
    renderer_->render(scene, frame_);
    return detector_.detect(frame_.bgr, frame_.depth, colour, camera());
  }

  static std::unique_ptr<SceneRenderer> renderer_;
  ColourBlobDetector detector_;
  RgbdFrame frame_;
};

std::unique_ptr<SceneRenderer> ColourBlobDetectorTest::renderer_;

// The palette's hues are 60 degrees apart: no detector takes another body's pixels. Within 20
// degrees (the two +-10 degree bands overlap) a body would be taken for a tracked one; a grey or
// black body never is.
TEST(ColourConfusion, OverlappingHueBandsAndOnlyThose) {
  using namespace palette;
  for (const Colour& a : {kBall, kTray, kLeftMug, kEndEffector, kRightMug, kCup})
    for (const Colour& b : {kBall, kTray, kLeftMug, kEndEffector, kRightMug, kCup})
      EXPECT_EQ(confusable(a, b), a.r == b.r && a.g == b.g && a.b == b.b);
  EXPECT_TRUE(confusable(kBall, Colour{255, 60, 0}));    // hue 14 degrees
  EXPECT_TRUE(confusable(kBall, Colour{255, 0, 60}));    // 346 degrees: across the wrap
  EXPECT_FALSE(confusable(kBall, Colour{255, 120, 0}));  // 28 degrees
  EXPECT_FALSE(confusable(kBall, kTable));
  EXPECT_FALSE(confusable(kBall, Colour{40, 0, 0}));  // dark: below min_value
}

TEST_F(ColourBlobDetectorTest, FullyVisibleBallIsFoundWithinAPixelOfItsProjectedCentre) {
  // On the axis, at the paper's hiding place, near the ball's end point and far out.
  for (const Eigen::Vector3d& centre :
       {Eigen::Vector3d(0.55, 0.0, kBallRadius), Eigen::Vector3d(0.4, 0.06, kBallRadius),
        Eigen::Vector3d(0.3, -0.35, kBallRadius), Eigen::Vector3d(0.75, 0.3, kBallRadius)}) {
    SceneSnapshot scene = table_scene();
    add(scene, ball(), pose_at(centre));
    const auto blob = detect(scene, palette::kBall);
    ASSERT_TRUE(blob.has_value()) << centre.transpose();
    const Eigen::Vector2d projected = *camera().project(centre);
    // Off the axis the silhouette is an ellipse centred a little outward of the centre's
    // projection (0.84 px at (0.3, -0.35)); against that exact centre the blob's centroid is
    // within 0.13 px anywhere in the image (measured), which checks that renderer and camera
    // model share one pixel grid.
    EXPECT_LT((blob->centroid_px - projected).norm(), 1.0) << centre.transpose();
    EXPECT_LT((blob->centroid_px - sphere_silhouette_centre(centre, kBallRadius, camera())).norm(),
              0.25)
        << centre.transpose();
    // The measured point is on the visible (upper) surface: within the radius of the centre
    // (plus 1 mm for the polyhedral sphere and the pixel grid), and nearer the camera.
    const double offset = (blob->surface_point_world - centre).norm();
    EXPECT_LT(offset, kBallRadius + 0.001) << centre.transpose();
    EXPECT_GT(offset, 0.5 * kBallRadius) << centre.transpose();
    EXPECT_LT((blob->surface_point_world - camera().position()).norm(),
              (centre - camera().position()).norm());
  }
}

TEST_F(ColourBlobDetectorTest, UncoveredBodiesShowTheirWholeExpectedSilhouette) {
  SceneSnapshot scene = table_scene();
  add(scene, ball(), pose_at(Eigen::Vector3d(0.45, -0.2, kBallRadius)));
  add(scene, mug(palette::kLeftMug), pose_at(Eigen::Vector3d(0.4, 0.15, 0.05)));
  const Eigen::Quaterniond yaw(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()));
  add(scene, make_body("tray", Shape::kBox, Eigen::Vector3d(0.2, 0.12, 0.02), palette::kTray),
      pose_at(Eigen::Vector3d(0.6, -0.05, 0.2), yaw));
  renderer_->render(scene, frame_);
  const auto blobs = detector_.detect_tracked(frame_.bgr, frame_.depth, scene.bodies, camera());
  ASSERT_EQ(blobs.size(), scene.bodies.size());
  EXPECT_FALSE(blobs[0].has_value());  // the table is not tracked
  for (std::size_t i = 1; i < scene.bodies.size(); ++i) {
    ASSERT_TRUE(blobs[i].has_value()) << scene.bodies[i].name;
    const double expected = expected_silhouette_area(scene.bodies[i], scene.poses[i], camera());
    // Measured at this camera over the image: ball 0.991-1.004, mug 0.998-1.001, tray (tilted)
    // 0.9999-1.0001; the inscribed polyhedra (-0.3%) and the pixels along the outline.
    EXPECT_NEAR(blobs[i]->area_px / expected, 1.0, 0.015) << scene.bodies[i].name;
  }
}

TEST_F(ColourBlobDetectorTest, BallUnderAMugIsMissing) {
  SceneSnapshot scene = table_scene();
  add(scene, ball(), pose_at(Eigen::Vector3d(0.4, 0.06, kBallRadius)));
  add(scene, mug(palette::kLeftMug), pose_at(Eigen::Vector3d(0.4, 0.06, 0.05)));
  EXPECT_FALSE(detect(scene, palette::kBall).has_value());
  EXPECT_TRUE(detector_.detect(frame_.bgr, frame_.depth, palette::kLeftMug, camera()).has_value());
}

TEST_F(ColourBlobDetectorTest, HalfCoveredBallIsBiasedAwayFromTheCoverWithHalfTheArea) {
  const Eigen::Vector3d centre(0.5, 0.0, kBallRadius);
  SceneSnapshot scene = table_scene();
  add(scene, ball(), pose_at(centre));
  const auto full = detect(scene, palette::kBall);
  ASSERT_TRUE(full.has_value());

  // A thin plate 0.15 m up whose edge hides exactly the image-left half of the ball: the edge is
  // the world line (y = const) that projects onto the ball centre's image column.
  const Eigen::Vector2d centre_px = *camera().project(centre);
  const double plate_z = 0.15;
  const double edge_y = camera().back_project(centre_px, kEye.z() - plate_z).y();
  add(scene, make_body("cover", Shape::kBox, Eigen::Vector3d(0.3, 0.3, 0.004), palette::kTray),
      pose_at(Eigen::Vector3d(0.5, edge_y + 0.15, plate_z)));
  const auto half = detect(scene, palette::kBall);
  ASSERT_TRUE(half.has_value());

  EXPECT_NEAR(half->area_px / full->area_px, 0.5, 0.05);
  // The centroid of a half disc is 4 R / (3 pi) = 0.42 R from the full disc's centre, on the
  // uncovered side (image right, since the cover is on the left).
  const double radius_px = std::sqrt(full->area_px / std::numbers::pi);
  const Eigen::Vector2d shift = half->centroid_px - full->centroid_px;
  EXPECT_GT(shift.x(), 0.35 * radius_px);
  EXPECT_LT(shift.x(), 0.5 * radius_px);
  EXPECT_LT(std::abs(shift.y()), 0.5);
  // The 3-D point moves with it: towards world -y (image right) by about that many pixels.
  EXPECT_LT(half->surface_point_world.y(), full->surface_point_world.y() - 0.005);
}

TEST_F(ColourBlobDetectorTest, BlobBelowTheMinimumAreaIsMissing) {
  SceneSnapshot scene = table_scene();
  add(scene, ball(), pose_at(Eigen::Vector3d(0.55, 0.0, kBallRadius)));
  const auto blob = detect(scene, palette::kBall);
  ASSERT_TRUE(blob.has_value());
  ColourBlobDetectorOptions options;
  options.min_area_pixels = static_cast<int>(blob->area_px) + 1;
  ColourBlobDetector strict(options);
  EXPECT_FALSE(strict.detect(frame_.bgr, frame_.depth, palette::kBall, camera()).has_value());
  options.min_area_pixels = static_cast<int>(blob->area_px);
  ColourBlobDetector exact(options);
  EXPECT_TRUE(exact.detect(frame_.bgr, frame_.depth, palette::kBall, camera()).has_value());
}

TEST_F(ColourBlobDetectorTest, PaletteColoursAreToldApartWithoutCrossTalk) {
  const Colour colours[] = {palette::kBall,        palette::kTray,     palette::kLeftMug,
                            palette::kEndEffector, palette::kRightMug, palette::kCup};
  SceneSnapshot scene = table_scene();
  int k = 0;
  for (const Colour& colour : colours) {
    // Touching neighbours on a ring: a detector that accepted a neighbour's hue would merge them.
    const double angle = 2.0 * std::numbers::pi * k++ / 6.0;
    add(scene, ball(colour),
        pose_at(
            Eigen::Vector3d(0.55 + 0.05 * std::cos(angle), 0.05 * std::sin(angle), kBallRadius)));
  }
  renderer_->render(scene, frame_);
  const auto blobs = detector_.detect_tracked(frame_.bgr, frame_.depth, scene.bodies, camera());
  for (std::size_t i = 1; i < scene.bodies.size(); ++i) {
    ASSERT_TRUE(blobs[i].has_value()) << i;
    const double expected = expected_silhouette_area(scene.bodies[i], scene.poses[i], camera());
    EXPECT_NEAR(blobs[i]->area_px / expected, 1.0, 0.015) << i;
    EXPECT_LT((blobs[i]->centroid_px - *camera().project(scene.poses[i].position)).norm(), 1.0)
        << i;
  }
}

TEST_F(ColourBlobDetectorTest, HueBandWrapsAroundRed) {
  // Hue 351 degrees (OpenCV 175): its +-10 degree band crosses 360, so it is split into OpenCV
  // hues [170, 179] and [0, 0].
  const Colour crimson{255, 0, 40};
  SceneSnapshot scene = table_scene();
  add(scene, ball(crimson), pose_at(Eigen::Vector3d(0.55, 0.0, kBallRadius)));
  const auto blob = detect(scene, crimson);
  ASSERT_TRUE(blob.has_value());
  EXPECT_NEAR(blob->area_px / expected_silhouette_area(scene.bodies[1], scene.poses[1], camera()),
              1.0, 0.015);
  // Pure red (hue 0) is within 10 degrees of it, so the crimson detector sees a red ball too.
  scene.bodies[1].colour = palette::kBall;
  EXPECT_TRUE(detect(scene, crimson).has_value());
  // Green is not.
  EXPECT_FALSE(detect(scene, palette::kLeftMug).has_value());
}

TEST_F(ColourBlobDetectorTest, BodiesOutOfViewGetNothing) {
  SceneSnapshot scene = table_scene();
  add(scene, ball(), pose_at(Eigen::Vector3d(2.0, 0.0, kBallRadius)));  // far outside the image
  renderer_->render(scene, frame_);
  const auto blobs = detector_.detect_tracked(frame_.bgr, frame_.depth, scene.bodies, camera());
  ASSERT_EQ(blobs.size(), 2u);
  EXPECT_FALSE(blobs[0].has_value());
  EXPECT_FALSE(blobs[1].has_value());
}

TEST(ColourBlobDetector, RejectsUnsaturatedColoursMismatchedImagesAndBadOptions) {
  ColourBlobDetector detector;
  const CameraModel camera;
  const cv::Mat bgr(480, 640, CV_8UC3, cv::Scalar(0, 0, 255));
  const cv::Mat depth(480, 640, CV_32FC1, cv::Scalar(0.5));
  EXPECT_THROW(detector.detect(bgr, depth, palette::kTable, camera), std::invalid_argument);
  EXPECT_THROW(detector.detect(bgr, cv::Mat(240, 320, CV_32FC1), palette::kBall, camera),
               std::invalid_argument);
  EXPECT_THROW(detector.detect(bgr, cv::Mat(480, 640, CV_64FC1), palette::kBall, camera),
               std::invalid_argument);
  ColourBlobDetectorOptions options;
  options.hue_tolerance_deg = 90.0;
  EXPECT_THROW(ColourBlobDetector{options}, std::invalid_argument);
}

TEST(ColourBlobDetector, WholeImageBlobBackProjectsAtItsMedianDepth) {
  ColourBlobDetector detector;
  const CameraModel camera = CameraModel::top_down(kEye);
  const cv::Mat bgr(480, 640, CV_8UC3, cv::Scalar(0, 0, 255));
  cv::Mat depth(480, 640, CV_32FC1, cv::Scalar(0.4f));
  depth.rowRange(0, 200).setTo(0.3f);    // fewer than half the pixels nearer
  depth.rowRange(200, 220).setTo(0.0f);  // no return: ignored
  const auto blob = detector.detect(bgr, depth, palette::kBall, camera);
  ASSERT_TRUE(blob.has_value());
  EXPECT_DOUBLE_EQ(blob->area_px, 640.0 * 480.0);
  EXPECT_NEAR(blob->centroid_px.x(), camera.cx, 1e-9);
  EXPECT_NEAR(blob->centroid_px.y(), camera.cy, 1e-9);
  EXPECT_FLOAT_EQ(static_cast<float>(blob->depth_m), 0.4f);
  EXPECT_LT((blob->surface_point_world - Eigen::Vector3d(0.55, 0.0, kEye.z() - 0.4)).norm(), 1e-6);
}

}  // namespace
}  // namespace opf::sim
