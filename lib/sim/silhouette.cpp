#include "opf/sim/silhouette.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <limits>
#include <vector>

namespace opf::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kRimPoints = 256;
constexpr int kContourPoints = 720;

// Camera-frame points on the body's outline-generating surface curves (see the header).
std::vector<Eigen::Vector3d> outline_points(const Body& body, const BodyPose& pose,
                                            const CameraModel& camera) {
  const Eigen::Isometry3d camera_from_world = camera.world_from_camera.inverse(Eigen::Isometry);
  const Eigen::Matrix3d rotation = pose.orientation.normalized().toRotationMatrix();
  const auto to_camera = [&](const Eigen::Vector3d& local) {
    return Eigen::Vector3d(camera_from_world * (pose.position + rotation * local));
  };

  std::vector<Eigen::Vector3d> points;
  switch (body.shape) {
    case Shape::kBox: {
      const Eigen::Vector3d half = 0.5 * body.size;
      for (int i = 0; i < 8; ++i) {
        points.push_back(to_camera(Eigen::Vector3d((i & 1) ? half.x() : -half.x(),
                                                   (i & 2) ? half.y() : -half.y(),
                                                   (i & 4) ? half.z() : -half.z())));
      }
      break;
    }
    case Shape::kCylinder: {
      const double radius = body.size.x();
      const double half_height = 0.5 * body.size.z();
      for (int i = 0; i < kRimPoints; ++i) {
        const double t = 2.0 * kPi * static_cast<double>(i) / kRimPoints;
        for (const double z : {-half_height, half_height}) {
          points.push_back(
              to_camera(Eigen::Vector3d(radius * std::cos(t), radius * std::sin(t), z)));
        }
      }
      break;
    }
    case Shape::kSphere: {
      // The viewing cone from the optical centre touches the sphere along a circle; its
      // projection is the silhouette (an ellipse off-axis), so sampling that circle is exact.
      const double radius = body.size.x();
      const Eigen::Vector3d centre = camera_from_world * pose.position;
      const double distance_sq = centre.squaredNorm();
      if (distance_sq <= radius * radius) return {};  // the camera is inside the sphere
      const double k = radius * radius / distance_sq;
      const Eigen::Vector3d circle_centre = centre * (1.0 - k);
      const double circle_radius = radius * std::sqrt(1.0 - k);
      const Eigen::Vector3d axis = centre.normalized();
      const Eigen::Vector3d e1 = axis.unitOrthogonal();
      const Eigen::Vector3d e2 = axis.cross(e1);
      for (int i = 0; i < kContourPoints; ++i) {
        const double t = 2.0 * kPi * static_cast<double>(i) / kContourPoints;
        points.push_back(circle_centre + circle_radius * (std::cos(t) * e1 + std::sin(t) * e2));
      }
      break;
    }
  }
  return points;
}

}  // namespace

double expected_silhouette_area(const Body& body, const BodyPose& pose, const CameraModel& camera) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (body.shape == Shape::kSphere) {
    const double z = camera.to_camera(pose.position).z();
    if (z <= -body.size.x()) return 0.0;
    if (z <= body.size.x()) return kNaN;  // crosses the camera plane
  }
  const std::vector<Eigen::Vector3d> points = outline_points(body, pose, camera);
  if (points.empty()) return kNaN;

  std::vector<cv::Point2f> projected;
  projected.reserve(points.size());
  int behind = 0;
  for (const Eigen::Vector3d& p : points) {
    if (!(p.z() > 0.0)) {
      ++behind;
      continue;
    }
    projected.emplace_back(static_cast<float>(camera.fx * p.x() / p.z() + camera.cx),
                           static_cast<float>(camera.fy * p.y() / p.z() + camera.cy));
  }
  if (behind == static_cast<int>(points.size())) return 0.0;
  if (behind > 0) return kNaN;

  std::vector<cv::Point2f> hull;
  cv::convexHull(projected, hull);
  return cv::contourArea(hull);
}

}  // namespace opf::sim
