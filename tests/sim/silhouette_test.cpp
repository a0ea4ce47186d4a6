#include "opf/sim/silhouette.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opf::sim {
namespace {

const Eigen::Vector3d kEye(0.55, 0.0, 0.8);  // paper experiment 2

Body make_body(Shape shape, const Eigen::Vector3d& size) {
  Body body;
  body.shape = shape;
  body.size = size;
  return body;
}

TEST(ExpectedSilhouetteArea, SphereOnTheAxisMatchesPiFROverZSquared) {
  const CameraModel camera = CameraModel::top_down(kEye);
  for (const double radius : {0.02, 0.025, 0.03}) {
    const Body sphere = make_body(Shape::kSphere, Eigen::Vector3d::Constant(radius));
    const double z = kEye.z() - radius;
    const double area =
        expected_silhouette_area(sphere, pose_at(Eigen::Vector3d(0.55, 0.0, radius)), camera);
    const double small_angle = std::numbers::pi * std::pow(camera.fx * radius / z, 2);
    EXPECT_NEAR(area / small_angle, 1.0, 0.03);
    // Exactly, the viewing cone's half-angle is asin(r / z): a circle of radius f r / sqrt(z^2 -
    // r^2), so the small-angle formula is 0.1% low here; the 720-gon is 1e-5 low.
    const double exact =
        std::numbers::pi * camera.fx * camera.fx * radius * radius / (z * z - radius * radius);
    EXPECT_NEAR(area / exact, 1.0, 1e-4);
  }
}

TEST(ExpectedSilhouetteArea, OffAxisSphereIsTheExactConicEllipse) {
  const CameraModel camera = CameraModel::top_down(kEye);
  const double radius = 0.03;
  const Eigen::Vector3d centre(0.35, 0.3, radius);
  const Eigen::Vector3d c = camera.to_camera(centre);
  // A circular cone, half-angle a, axis t off the optical axis, cut by the image plane: semi-axes
  // f sin a cos a / (cos^2 t - sin^2 a) and f sin a / sqrt(cos^2 t - sin^2 a).
  const double cos_t = c.z() / c.norm();
  const double sin_a = radius / c.norm();
  const double cos_a = std::sqrt(1.0 - sin_a * sin_a);
  const double denominator = cos_t * cos_t - sin_a * sin_a;
  const double ellipse = std::numbers::pi * (camera.fx * sin_a * cos_a / denominator) *
                         (camera.fx * sin_a / std::sqrt(denominator));
  const double area = expected_silhouette_area(
      make_body(Shape::kSphere, Eigen::Vector3d::Constant(radius)), pose_at(centre), camera);
  EXPECT_NEAR(area / ellipse, 1.0, 1e-4);
  // And it is larger than on the axis at the same distance.
  EXPECT_GT(ellipse, std::numbers::pi * std::pow(camera.fx * radius, 2) /
                         (c.squaredNorm() - radius * radius));
}

TEST(ExpectedSilhouetteArea, BoxSeenFromAboveIsItsTopFace) {
  const CameraModel camera = CameraModel::top_down(kEye);
  const Body box = make_body(Shape::kBox, Eigen::Vector3d(0.2, 0.12, 0.02));
  const double top_depth = kEye.z() - 0.21;
  const double top_face = (camera.fx * 0.2 / top_depth) * (camera.fy * 0.12 / top_depth);
  // Centred under the lens, the bottom face projects inside the top face, for any yaw.
  for (const double yaw : {0.0, 0.4, 1.3}) {
    const Eigen::Quaterniond q(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
    EXPECT_NEAR(expected_silhouette_area(box, pose_at(Eigen::Vector3d(0.55, 0.0, 0.2), q), camera) /
                    top_face,
                1.0, 1e-5);
  }
}

TEST(ExpectedSilhouetteArea, UprightCylinderUnderTheLensIsItsTopDisc) {
  const CameraModel camera = CameraModel::top_down(kEye);
  const Body mug = make_body(Shape::kCylinder, Eigen::Vector3d(0.04, 0.04, 0.1));
  const double top_depth = kEye.z() - 0.1;
  const double disc = std::numbers::pi * std::pow(camera.fx * 0.04 / top_depth, 2);
  // The 256-gon on the rim is 1e-4 smaller than the disc.
  EXPECT_NEAR(
      expected_silhouette_area(mug, pose_at(Eigen::Vector3d(0.55, 0.0, 0.05)), camera) / disc, 1.0,
      2e-4);
  // Lying on its side (axis along world x) it shows a rectangle-ish outline, much larger.
  const Eigen::Quaterniond lying(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()));
  EXPECT_GT(expected_silhouette_area(mug, pose_at(Eigen::Vector3d(0.55, 0.0, 0.04), lying), camera),
            1.1 * disc);
}

TEST(ExpectedSilhouetteArea, IsTheWholeBodysPastTheImageEdgeToo) {
  const CameraModel camera = CameraModel::top_down(kEye);
  // A paper-thin plate (1 um), whose side adds nothing even far off the axis: parallel to the
  // image plane, its projection has the same area wherever it lies at one depth.
  const Body plate = make_body(Shape::kBox, Eigen::Vector3d(0.1, 0.1, 1e-6));
  const double z = 0.0;
  // Centred on the image's right edge (u = width - 0.5): where that column meets the top face.
  const double edge_y =
      camera.back_project(Eigen::Vector2d(camera.width - 0.5, camera.cy), kEye.z() - z).y();
  const double straddling =
      expected_silhouette_area(plate, pose_at(Eigen::Vector3d(0.55, edge_y, z)), camera);
  const double inside =
      expected_silhouette_area(plate, pose_at(Eigen::Vector3d(0.55, 0.0, z)), camera);
  const double outside =
      expected_silhouette_area(plate, pose_at(Eigen::Vector3d(0.55, 3.0, z)), camera);
  EXPECT_NEAR(straddling / inside, 1.0, 1e-3);
  EXPECT_NEAR(outside / inside, 1.0, 1e-3);
}

TEST(ExpectedSilhouetteArea, BehindTheCameraIsZeroAndAcrossItIsNaN) {
  const CameraModel camera = CameraModel::top_down(kEye);
  const Body ball = make_body(Shape::kSphere, Eigen::Vector3d::Constant(0.03));
  const Body box = make_body(Shape::kBox, Eigen::Vector3d(0.1, 0.1, 0.1));
  EXPECT_EQ(expected_silhouette_area(ball, pose_at(Eigen::Vector3d(0.55, 0.0, 1.2)), camera), 0.0);
  EXPECT_EQ(expected_silhouette_area(box, pose_at(Eigen::Vector3d(0.55, 0.0, 1.2)), camera), 0.0);
  EXPECT_TRUE(
      std::isnan(expected_silhouette_area(ball, pose_at(Eigen::Vector3d(0.7, 0.0, 0.81)), camera)));
  EXPECT_TRUE(
      std::isnan(expected_silhouette_area(box, pose_at(Eigen::Vector3d(0.7, 0.0, 0.8)), camera)));
  // The camera inside a sphere.
  EXPECT_TRUE(std::isnan(expected_silhouette_area(
      make_body(Shape::kSphere, Eigen::Vector3d::Constant(0.5)), pose_at(kEye), camera)));
}

}  // namespace
}  // namespace opf::sim
