#include "opf/sim/scene_renderer.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <thread>

#include "opf/sim/colour_blob_detector.h"

namespace opf::sim {
namespace {

const Eigen::Vector3d kEye(0.55, 0.0, 0.49);  // paper experiment 1

// Measured over table planes 0.2-1.1 m from the lens (Mesa llvmpipe, highp shader, 0.1-3 m
// clip): worst |rendered - true z-depth| 0.083 mm, mean -0.018 mm. What remains is MRPT's depth
// look-up table, which truncates the [0, 1] depth buffer to 2^17 steps: one step is
// 7.6e-6 (far - near) z^2 / (far near) = 0.074 mm x (z / 1 m)^2, 0.09 mm at 1.1 m. (With MRPT's
// own mediump shader the same sweep is off by up to 3.4 mm.)
constexpr double kDepthTolerance = 1.0e-4;

// A 1.2 m x 1.2 m grey table whose top is the plane z = 0.
void add_table(SceneSnapshot& scene) {
  scene.bodies.push_back(
      make_body("table", Shape::kBox, Eigen::Vector3d(1.2, 1.2, 0.04), palette::kTable, false));
  scene.poses.push_back(pose_at(Eigen::Vector3d(0.55, 0.0, -0.02)));
}

void add(SceneSnapshot& scene, const Body& body, const BodyPose& pose) {
  scene.bodies.push_back(body);
  scene.poses.push_back(pose);
}

// Centroid (and area) of the red pixels: bodies drawn in palette::kBall stay pure red under any
// shading (blue and green remain 0).
Eigen::Vector2d red_centroid(const cv::Mat& bgr, double* area = nullptr) {
  cv::Mat mask;
  cv::inRange(bgr, cv::Scalar(0, 0, 100), cv::Scalar(0, 0, 255), mask);
  const cv::Moments m = cv::moments(mask, true);
  if (area != nullptr) *area = m.m00;
  return {m.m10 / m.m00, m.m01 / m.m00};
}

class SceneRendererTest : public ::testing::Test {
 protected:
  // One context for the suite: MRPT allows only one at a time, and the first costs ~0.15 s.
  static void SetUpTestSuite() {
    renderer_ = std::make_unique<SceneRenderer>(CameraModel::top_down(kEye));
  }
  static void TearDownTestSuite() { renderer_.reset(); }
  void SetUp() override { renderer_->set_camera(CameraModel::top_down(kEye)); }

  static std::unique_ptr<SceneRenderer> renderer_;
};

std::unique_ptr<SceneRenderer> SceneRendererTest::renderer_;

TEST_F(SceneRendererTest, FrameHasTheCameraSizeAndTypes) {
  SceneSnapshot scene;
  add_table(scene);
  const RgbdFrame frame = renderer_->render(scene);
  EXPECT_EQ(frame.bgr.rows, 480);
  EXPECT_EQ(frame.bgr.cols, 640);
  EXPECT_EQ(frame.bgr.type(), CV_8UC3);
  EXPECT_EQ(frame.depth.rows, 480);
  EXPECT_EQ(frame.depth.cols, 640);
  EXPECT_EQ(frame.depth.type(), CV_32FC1);
}

TEST_F(SceneRendererTest, TableDepthIsTheTrueZDepthAtEveryPixel) {
  SceneSnapshot scene;
  add_table(scene);
  const RgbdFrame frame = renderer_->render(scene);
  double worst = 0.0;
  for (int r = 0; r < frame.depth.rows; ++r) {
    for (int c = 0; c < frame.depth.cols; ++c) {
      worst = std::max(worst, std::abs(frame.depth.at<float>(r, c) - 0.49));
    }
  }
  EXPECT_LT(worst, kDepthTolerance);
}

TEST_F(SceneRendererTest, BoxTopDepthBackProjectsOntoTheBoxTop) {
  SceneSnapshot scene;
  add_table(scene);
  // The paper's tray: 20 cm x 12 cm, its top 0.21 m above the table.
  add(scene, make_body("tray", Shape::kBox, Eigen::Vector3d(0.2, 0.12, 0.02), palette::kTray),
      pose_at(Eigen::Vector3d(0.55, -0.09, 0.2)));
  const CameraModel& camera = renderer_->camera();
  const RgbdFrame frame = renderer_->render(scene);
  int checked = 0;
  for (double dx = -0.09; dx <= 0.09; dx += 0.01) {
    for (double dy = -0.05; dy <= 0.05; dy += 0.01) {
      const auto pixel = camera.project(Eigen::Vector3d(0.55 + dx, -0.09 + dy, 0.21));
      ASSERT_TRUE(pixel.has_value());
      const int c = static_cast<int>(std::lround(pixel->x()));
      const int r = static_cast<int>(std::lround(pixel->y()));
      const double depth = frame.depth.at<float>(r, c);
      EXPECT_NEAR(depth, 0.28, kDepthTolerance);
      const Eigen::Vector3d back = camera.back_project(Eigen::Vector2d(c, r), depth);
      EXPECT_NEAR(back.z(), 0.21, kDepthTolerance);
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

// A tilted camera sees the table at a different z-depth in every pixel: the rendered depth must
// be z-depth (not range) and the pixel grid must line up with CameraModel to a fraction of a
// pixel, or the back-projected points would leave the plane.
TEST_F(SceneRendererTest, TiltedCameraDepthBackProjectsOntoTheTablePlane) {
  const CameraModel camera = CameraModel::look_at(
      Eigen::Vector3d(0.1, -0.35, 0.55), Eigen::Vector3d(0.55, 0.0, 0.0), Eigen::Vector3d::UnitZ());
  renderer_->set_camera(camera);
  SceneSnapshot scene;
  add_table(scene);
  const RgbdFrame frame = renderer_->render(scene);
  double worst_depth = 0.0;
  int checked = 0;
  for (int r = 5; r < camera.height; r += 10) {
    for (int c = 5; c < camera.width; c += 10) {
      const double depth = frame.depth.at<float>(r, c);
      // The true z-depth where this pixel's ray meets z = 0.
      const Eigen::Vector3d unit = camera.back_project(Eigen::Vector2d(c, r), 1.0);
      const double along = camera.position().z() / (camera.position().z() - unit.z());
      const Eigen::Vector3d hit = camera.position() + along * (unit - camera.position());
      if (along <= 0.0 || std::abs(hit.x() - 0.55) > 0.59 || std::abs(hit.y()) > 0.59) continue;
      worst_depth = std::max(worst_depth, std::abs(depth - along));
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
  EXPECT_LT(worst_depth, kDepthTolerance);
}

TEST_F(SceneRendererTest, SurfacesFacingTheCameraShowTheirExactColour) {
  SceneSnapshot scene;
  add_table(scene);
  const RgbdFrame frame = renderer_->render(scene);
  const cv::Vec3b centre = frame.bgr.at<cv::Vec3b>(240, 320);
  EXPECT_NEAR(centre[0], palette::kTable.b, 1);
  EXPECT_NEAR(centre[1], palette::kTable.g, 1);
  EXPECT_NEAR(centre[2], palette::kTable.r, 1);
}

TEST_F(SceneRendererTest, EmptyViewShowsBackgroundWithNoDepth) {
  // Only the table, 4 m below a camera whose far clip is 3 m: nothing is drawn.
  renderer_->set_camera(CameraModel::top_down(Eigen::Vector3d(0.55, 0.0, 4.0)));
  SceneSnapshot scene;
  add_table(scene);
  const RgbdFrame frame = renderer_->render(scene);
  EXPECT_EQ(cv::countNonZero(frame.depth), 0);
  const Colour bg = renderer_->options().background;
  cv::Mat differs;
  cv::inRange(frame.bgr, cv::Scalar(bg.b, bg.g, bg.r), cv::Scalar(bg.b, bg.g, bg.r), differs);
  EXPECT_EQ(cv::countNonZero(differs), 640 * 480);
}

TEST_F(SceneRendererTest, RenderingIsDeterministic) {
  SceneSnapshot scene;
  add_table(scene);
  add(scene, make_body("ball", Shape::kSphere, Eigen::Vector3d::Constant(0.025), palette::kBall),
      pose_at(Eigen::Vector3d(0.4, 0.06, 0.025)));
  add(scene,
      make_body("mug", Shape::kCylinder, Eigen::Vector3d(0.04, 0.04, 0.1), palette::kLeftMug),
      pose_at(Eigen::Vector3d(0.45, 0.12, 0.05)));
  const RgbdFrame first = renderer_->render(scene);
  SceneSnapshot other = scene;
  other.poses[1].position.x() += 0.1;
  renderer_->render(other);
  const RgbdFrame again = renderer_->render(scene);
  EXPECT_EQ(cv::norm(first.bgr, again.bgr, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(first.depth, again.depth, cv::NORM_INF), 0.0);
}

TEST_F(SceneRendererTest, MovingABodyMovesItsImageByItsProjection) {
  const CameraModel& camera = renderer_->camera();
  SceneSnapshot scene;
  add_table(scene);
  add(scene, make_body("ball", Shape::kSphere, Eigen::Vector3d::Constant(0.025), palette::kBall),
      pose_at(Eigen::Vector3d(0.55, 0.0, 0.025)));
  RgbdFrame frame;
  renderer_->render(scene, frame);
  const Eigen::Vector2d before = red_centroid(frame.bgr);
  const Eigen::Vector3d moved(0.62, -0.08, 0.025);
  scene.poses[1].position = moved;
  renderer_->render(scene, frame);
  const Eigen::Vector2d after = red_centroid(frame.bgr);
  const Eigen::Vector2d shift =
      *camera.project(moved) - *camera.project(Eigen::Vector3d(0.55, 0.0, 0.025));
  // Off the axis the sphere's silhouette is a slightly elongated ellipse whose centroid sits a
  // little outward of the centre's projection; 0.3 px covers it at this distance.
  EXPECT_LT((after - before - shift).norm(), 0.3);
}

TEST_F(SceneRendererTest, CylinderIsCentredOnItsPoseAndBoxesFollowTheirOrientation) {
  const CameraModel& camera = renderer_->camera();
  SceneSnapshot scene;
  add_table(scene);
  // A 10 cm mug standing on the table: its centre is 5 cm up, so its top is 0.39 m from the lens.
  add(scene,
      make_body("mug", Shape::kCylinder, Eigen::Vector3d(0.04, 0.04, 0.1), palette::kRightMug),
      pose_at(Eigen::Vector3d(0.5, 0.1, 0.05)));
  // A 16 cm x 2 cm red bar turned 90 degrees about z: long along world y (image horizontal).
  const Eigen::Quaterniond quarter(
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()));
  add(scene, make_body("bar", Shape::kBox, Eigen::Vector3d(0.16, 0.02, 0.02), palette::kBall),
      pose_at(Eigen::Vector3d(0.65, -0.1, 0.01), quarter));
  const RgbdFrame frame = renderer_->render(scene);

  const auto mug_top = camera.project(Eigen::Vector3d(0.5, 0.1, 0.1));
  ASSERT_TRUE(mug_top.has_value());
  const int r = static_cast<int>(std::lround(mug_top->y()));
  const int c = static_cast<int>(std::lround(mug_top->x()));
  EXPECT_NEAR(frame.depth.at<float>(r, c), 0.39, kDepthTolerance);
  const cv::Vec3b mug_colour = frame.bgr.at<cv::Vec3b>(r, c);
  EXPECT_EQ(mug_colour, cv::Vec3b(255, 0, 0));

  cv::Mat bar;
  cv::inRange(frame.bgr, cv::Scalar(0, 0, 100), cv::Scalar(0, 0, 255), bar);
  const cv::Rect box = cv::boundingRect(bar);
  // 16 cm at 0.47 m is ~106 px wide, 2 cm ~13 px tall (plus the sides seen off-axis).
  EXPECT_GT(box.width, 100);
  EXPECT_LT(box.height, 25);
}

TEST_F(SceneRendererTest, RebuildsWhenTheBodiesChange) {
  SceneSnapshot scene;
  add_table(scene);
  add(scene, make_body("ball", Shape::kSphere, Eigen::Vector3d::Constant(0.02), palette::kBall),
      pose_at(Eigen::Vector3d(0.55, 0.0, 0.02)));
  RgbdFrame frame;
  renderer_->render(scene, frame);
  double small = 0.0;
  red_centroid(frame.bgr, &small);
  scene.bodies[1].size = Eigen::Vector3d::Constant(0.03);
  renderer_->render(scene, frame);
  double large = 0.0;
  red_centroid(frame.bgr, &large);
  EXPECT_NEAR(large / small, 2.25, 0.1);  // area ~ r^2
  scene.bodies.pop_back();
  scene.poses.pop_back();
  renderer_->render(scene, frame);
  double none = 0.0;
  red_centroid(frame.bgr, &none);
  EXPECT_EQ(none, 0.0);
}

TEST_F(SceneRendererTest, RejectsMismatchedSnapshotsAndCameraSizes) {
  SceneSnapshot scene;
  add_table(scene);
  scene.poses.clear();
  EXPECT_THROW(renderer_->render(scene), std::invalid_argument);
  EXPECT_THROW(renderer_->set_camera(CameraModel::top_down(kEye, 1.0, 320, 240)),
               std::invalid_argument);
}

TEST_F(SceneRendererTest, ASecondLiveRendererIsRefused) {
  EXPECT_THROW(SceneRenderer(CameraModel::top_down(kEye)), std::logic_error);
  // The refusal must not disturb the live one.
  SceneSnapshot scene;
  add_table(scene);
  EXPECT_NEAR(renderer_->render(scene).depth.at<float>(240, 320), 0.49, kDepthTolerance);
}

TEST_F(SceneRendererTest, RendersOnlyFromItsOwnThread) {
  SceneSnapshot scene;
  add_table(scene);
  bool refused = false;
  std::thread other([&] {
    try {
      renderer_->render(scene);
    } catch (const std::logic_error&) {
      refused = true;
    }
  });
  other.join();
  EXPECT_TRUE(refused);
  EXPECT_NEAR(renderer_->render(scene).depth.at<float>(240, 320), 0.49, kDepthTolerance);
}

TEST_F(SceneRendererTest, RejectsBadOptions) {
  SceneRendererOptions options;
  options.near_clip_m = 0.0;
  EXPECT_THROW(SceneRenderer(CameraModel(), options), std::invalid_argument);
  options = {};
  options.far_clip_m = 0.05;
  EXPECT_THROW(SceneRenderer(CameraModel(), options), std::invalid_argument);
  options = {};
  options.sphere_divisions = 2;
  EXPECT_THROW(SceneRenderer(CameraModel(), options), std::invalid_argument);
}

}  // namespace
}  // namespace opf::sim
