#include "opf/sim/camera_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace opf::sim {
namespace {

const Eigen::Vector3d kExperiment1Eye(0.55, 0.0, 0.49);
const Eigen::Vector3d kExperiment2Eye(0.55, 0.0, 0.8);

TEST(CameraModel, DefaultsAre640x480With75DegreeVerticalFovAndCentredPrincipalPoint) {
  const CameraModel camera;
  EXPECT_EQ(camera.width, 640);
  EXPECT_EQ(camera.height, 480);
  EXPECT_NEAR(camera.vertical_fov_rad(), 75.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(camera.fx, camera.fy);
  EXPECT_NEAR(camera.fy, 240.0 / std::tan(37.5 * std::numbers::pi / 180.0), 1e-9);
  EXPECT_DOUBLE_EQ(camera.cx, 319.5);
  EXPECT_DOUBLE_EQ(camera.cy, 239.5);
}

TEST(CameraModel, ProjectsAKnownCameraFramePointToItsPinholePixel) {
  const CameraModel camera = CameraModel::top_down(kExperiment2Eye);
  // Camera frame of top_down: x = world -y, y = world -x, z = world -z.
  const Eigen::Vector3d world(0.55 - 0.05, 0.0 - 0.1, 0.8 - 0.7);
  double depth = 0.0;
  const auto pixel = camera.project(world, &depth);
  ASSERT_TRUE(pixel.has_value());
  EXPECT_NEAR(depth, 0.7, 1e-12);
  EXPECT_NEAR(pixel->x(), camera.cx + camera.fx * 0.1 / 0.7, 1e-9);
  EXPECT_NEAR(pixel->y(), camera.cy + camera.fy * 0.05 / 0.7, 1e-9);
}

TEST(CameraModel, TopDownImageHasWorldXUpAndWorldYLeft) {
  const CameraModel camera = CameraModel::top_down(kExperiment1Eye);
  const auto centre = camera.project(Eigen::Vector3d(0.55, 0.0, 0.0));
  const auto further = camera.project(Eigen::Vector3d(0.65, 0.0, 0.0));
  const auto left_mug = camera.project(Eigen::Vector3d(0.4, 0.15, 0.03));
  const auto right_mug = camera.project(Eigen::Vector3d(0.4, -0.15, 0.03));
  ASSERT_TRUE(centre && further && left_mug && right_mug);
  EXPECT_NEAR(centre->x(), camera.cx, 1e-9);
  EXPECT_NEAR(centre->y(), camera.cy, 1e-9);
  EXPECT_LT(further->y(), centre->y());  // world +x is up in the image
  EXPECT_NEAR(further->x(), centre->x(), 1e-9);
  EXPECT_LT(left_mug->x(), camera.cx);  // the paper's "left" mug (y = +0.15) is on the left
  EXPECT_GT(right_mug->x(), camera.cx);
  EXPECT_NEAR(camera.forward().z(), -1.0, 1e-15);
  EXPECT_NEAR(camera.world_from_camera.linear().determinant(), 1.0, 1e-12);
}

TEST(CameraModel, ProjectAndBackProjectRoundTripWithinAMicrometreAtTableDistance) {
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (const Eigen::Vector3d& eye : {kExperiment1Eye, kExperiment2Eye}) {
    const CameraModel camera = CameraModel::top_down(eye);
    for (int i = 0; i < 200; ++i) {
      // Points 0.5-0.8 m in front of the lens, anywhere in the field of view.
      const double depth = 0.65 + 0.15 * uniform(generator);
      const Eigen::Vector2d pixel(camera.cx + camera.cx * uniform(generator),
                                  camera.cy + camera.cy * uniform(generator));
      const Eigen::Vector3d world = camera.back_project(pixel, depth);
      double projected_depth = 0.0;
      const auto reprojected = camera.project(world, &projected_depth);
      ASSERT_TRUE(reprojected.has_value());
      EXPECT_LT((*reprojected - pixel).norm(), 1e-9);
      EXPECT_NEAR(projected_depth, depth, 1e-12);
      EXPECT_LT((camera.back_project(*reprojected, projected_depth) - world).norm(), 1e-6);
    }
  }
}

TEST(CameraModel, PointsBehindOrOnTheCameraPlaneDoNotProject) {
  const CameraModel camera = CameraModel::top_down(kExperiment1Eye);
  double depth = 0.0;
  EXPECT_FALSE(camera.project(Eigen::Vector3d(0.55, 0.1, 0.6), &depth).has_value());
  EXPECT_NEAR(depth, -0.11, 1e-12);
  EXPECT_FALSE(camera.project(Eigen::Vector3d(0.6, 0.1, 0.49)).has_value());
}

TEST(CameraModel, ImageEdgesAreHalfTheVerticalFovFromTheAxis) {
  const CameraModel camera = CameraModel::top_down(kExperiment2Eye);
  const double half = 0.5 * camera.vertical_fov_rad();
  // The top edge of the image (row -0.5) is the ray tilted by half the FOV towards world +x.
  const Eigen::Vector3d top = camera.back_project(Eigen::Vector2d(camera.cx, -0.5), 1.0);
  const Eigen::Vector3d ray = top - camera.position();
  EXPECT_NEAR(std::atan2(ray.x(), -ray.z()), half, 1e-12);
}

TEST(CameraModel, DefaultFovSeesBothPaperScenes) {
  const CameraModel high = CameraModel::top_down(kExperiment2Eye);
  // Sugar dropping: the mug (radius ~4 cm, 10 cm tall) from y = +0.45 to -0.45.
  for (const double y : {0.49, -0.49}) {
    const auto p = high.project(Eigen::Vector3d(0.55, y, 0.1));
    ASSERT_TRUE(p.has_value());
    EXPECT_TRUE(high.in_image(*p)) << "y = " << y;
  }
  const CameraModel low = CameraModel::top_down(kExperiment1Eye);
  // General tracking: the ball's end point, the mug at x = 0.8 (top at ~0.08 m), the tray.
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(0.3, -0.375, 0.0), Eigen::Vector3d(0.84, 0.15, 0.08),
        Eigen::Vector3d(0.26, 0.15, 0.08), Eigen::Vector3d(0.55, -0.09, 0.2)}) {
    const auto pixel = low.project(p);
    ASSERT_TRUE(pixel.has_value());
    EXPECT_TRUE(low.in_image(*pixel)) << p.transpose();
  }
}

TEST(CameraModel, LookAtPutsTheTargetOnTheAxisAndUpUpwards) {
  const Eigen::Vector3d eye(0.1, -0.4, 0.7);
  const Eigen::Vector3d target(0.6, 0.1, 0.0);
  const CameraModel camera =
      CameraModel::look_at(eye, target, Eigen::Vector3d::UnitZ(), 1.0, 320, 240);
  EXPECT_EQ(camera.width, 320);
  EXPECT_NEAR(camera.vertical_fov_rad(), 1.0, 1e-12);
  const auto on_axis = camera.project(target);
  ASSERT_TRUE(on_axis.has_value());
  EXPECT_NEAR(on_axis->x(), camera.cx, 1e-9);
  EXPECT_NEAR(on_axis->y(), camera.cy, 1e-9);
  const auto above = camera.project(target + Eigen::Vector3d(0, 0, 0.05));
  ASSERT_TRUE(above.has_value());
  EXPECT_LT(above->y(), on_axis->y());
  EXPECT_NEAR(camera.world_from_camera.linear().determinant(), 1.0, 1e-12);
  EXPECT_LT((camera.forward() - (target - eye).normalized()).norm(), 1e-12);
}

TEST(CameraModel, LookAtRejectsDegenerateInput) {
  const Eigen::Vector3d eye(0, 0, 1);
  EXPECT_THROW(CameraModel::look_at(eye, eye, Eigen::Vector3d::UnitX()), std::invalid_argument);
  EXPECT_THROW(CameraModel::look_at(eye, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()),
               std::invalid_argument);
  EXPECT_THROW(CameraModel::look_at(eye, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.0),
               std::invalid_argument);
  EXPECT_THROW(
      CameraModel::look_at(eye, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 1.0, 0, 480),
      std::invalid_argument);
}

// The experiment reader names the key from the same test (camera.look_at, camera.up).
TEST(CameraModel, LookAtFaultNamesWhatIsDegenerate) {
  const Eigen::Vector3d eye(0, 0, 1);
  EXPECT_EQ(look_at_fault(eye, eye, Eigen::Vector3d::UnitX()), LookAtFault::kTargetAtEye);
  EXPECT_EQ(look_at_fault(eye, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 3)),
            LookAtFault::kUpAlongView);
  EXPECT_EQ(look_at_fault(eye, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()),
            LookAtFault::kNone);
}

TEST(CameraModel, InImageUsesPixelEdges) {
  const CameraModel camera;
  EXPECT_TRUE(camera.in_image(Eigen::Vector2d(-0.5, -0.5)));
  EXPECT_TRUE(camera.in_image(Eigen::Vector2d(639.49, 479.49)));
  EXPECT_FALSE(camera.in_image(Eigen::Vector2d(639.5, 0.0)));
  EXPECT_FALSE(camera.in_image(Eigen::Vector2d(0.0, -0.51)));
}

}  // namespace
}  // namespace opf::sim
