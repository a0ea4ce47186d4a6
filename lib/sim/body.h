#pragma once
// The simulator's vocabulary: a rigid body of the scene (shape, size, colour) and a snapshot of
// every body's pose at one instant, which the renderer draws and the experiments score against.

#include "opf/core/enum_names.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <vector>

namespace opf::sim {

/// Every shape's origin is its geometric centre; the cylinder's axis is its local z.
enum class Shape { kSphere, kCylinder, kBox };
inline constexpr EnumNames<Shape, 3> kShapeNames = {
    {{Shape::kSphere, "sphere"}, {Shape::kCylinder, "cylinder"}, {Shape::kBox, "box"}}};

struct Colour {
  std::uint8_t r = 0, g = 0, b = 0;
};

struct Body {
  std::string name;
  Shape shape = Shape::kSphere;
  /// Sphere: radius in x. Cylinder: radius in x, height in z. Box: full extents x, y, z. Metres.
  Eigen::Vector3d size = Eigen::Vector3d(0.02, 0.02, 0.02);
  Colour colour;
  /// Tracked bodies are detected by colour and estimated; the others (table, robot) only render
  /// and occlude.
  bool tracked = true;
};

struct BodyPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

inline Body make_body(std::string name, Shape shape, const Eigen::Vector3d& size, Colour colour,
                      bool tracked = true) {
  Body body;
  body.name = std::move(name);
  body.shape = shape;
  body.size = size;
  body.colour = colour;
  body.tracked = tracked;
  return body;
}

inline BodyPose pose_at(const Eigen::Vector3d& position,
                        const Eigen::Quaterniond& orientation = Eigen::Quaterniond::Identity()) {
  BodyPose pose;
  pose.position = position;
  pose.orientation = orientation;
  return pose;
}

/// The scene at one instant: poses[i] is the pose of bodies[i].
struct SceneSnapshot {
  double t = 0.0;
  std::vector<Body> bodies;
  std::vector<BodyPose> poses;
};

}  // namespace opf::sim
