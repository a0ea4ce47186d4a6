#include "opf/sim/camera_sensor.h"

#include "opf/sim/silhouette.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace opf::sim {

CameraSensor::CameraSensor(const CameraModel& camera, const SceneRendererOptions& render,
                           const ColourBlobDetectorOptions& detect)
    : camera_(camera), renderer_(camera, render), detector_(detect) {}

CameraFrame CameraSensor::observe(const SceneSnapshot& scene) {
  renderer_.render(scene, image_);
  const auto blobs = detector_.detect_tracked(image_.bgr, image_.depth, scene.bodies, camera_);
  CameraFrame frame;
  frame.t = scene.t;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& body = scene.bodies[i];
    if (!body.tracked) continue;
    Sighting sighting;
    sighting.object = body.name;
    if (blobs[i]) {
      const double expected = expected_silhouette_area(body, scene.poses[i], camera_);
      sighting.detected = true;
      sighting.visible_fraction =
          expected > 0.0 ? std::min(1.0, blobs[i]->area_px / expected) : 0.0;
      const double depth = blobs[i]->depth_m + centre_depth_offset(body, scene.poses[i], camera_);
      sighting.position = camera_.back_project(blobs[i]->centroid_px, depth);
      sighting.partial_view_offset =
          partial_view_offset(sighting.visible_fraction, expected, depth, camera_);
      sighting.radius = silhouette_radius(expected, depth, camera_);
      if (body.shape == Shape::kBox) sighting.box = body.size;
    }
    frame.sightings.push_back(sighting);
  }
  return frame;
}

double partial_view_offset(double visible_fraction, double expected_area_px, double depth,
                           const CameraModel& camera) {
  if (!(visible_fraction < 1.0)) return 0.0;
  return (1.0 - std::max(visible_fraction, 0.0)) *
         silhouette_radius(expected_area_px, depth, camera);
}

double silhouette_radius(double expected_area_px, double depth, const CameraModel& camera) {
  if (!(expected_area_px > 0.0)) return 0.0;
  const double radius_px = std::sqrt(expected_area_px / std::numbers::pi);
  return radius_px * depth / std::sqrt(camera.fx * camera.fy);
}

double centre_depth_offset(const Body& body, const BodyPose& pose, const CameraModel& camera) {
  // The visible surface is mostly the face (or cap) turned towards the camera; the offset is the
  // z-depth between that face's median point and the centre.
  const Eigen::Vector3d to_camera = (camera.position() - pose.position).normalized();
  const Eigen::Vector3d towards = pose.orientation.conjugate() * to_camera;  // body frame
  const Eigen::Vector3d forward = pose.orientation.conjugate() * camera.forward();
  switch (body.shape) {
    case Shape::kSphere:
      // The cap faces the camera: its median point lies r / sqrt(2) from the centre along the ray.
      return body.size.x() / std::sqrt(2.0) * std::abs(to_camera.dot(camera.forward()));
    case Shape::kCylinder: {
      const double r = body.size.x(), h = body.size.z();
      const double along = std::abs(towards.z());
      const double across = std::sqrt(std::max(0.0, 1.0 - along * along));
      // The end disc while the camera is within 45 degrees of the axis: its pixels are the
      // nearest and hold the blob's median depth even when the side shows as much area.
      if (along >= across) return 0.5 * h * std::abs(forward.z());
      // The side: a half cylinder whose median depth is sqrt(3)/2 r in front of the axis.
      const Eigen::Vector3d radial = Eigen::Vector3d(towards.x(), towards.y(), 0.0).normalized();
      return std::sqrt(3.0) / 2.0 * r * std::abs(forward.dot(radial));
    }
    case Shape::kBox: {
      // The face most directly facing the camera (see the cylinder).
      int face = 0;
      for (int i = 1; i < 3; ++i)
        if (std::abs(towards[i]) > std::abs(towards[face])) face = i;
      return 0.5 * body.size[face] * std::abs(forward[face]);
    }
  }
  return 0.0;
}

}  // namespace opf::sim
