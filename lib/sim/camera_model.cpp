#include "opf/sim/camera_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace opf::sim {
namespace {

void set_intrinsics(CameraModel& camera, double vertical_fov_rad, int width, int height) {
  if (!(vertical_fov_rad > 0.0 && vertical_fov_rad < 3.14159265358979323846)) {
    throw std::invalid_argument("CameraModel: the vertical field of view must be in (0, pi)");
  }
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("CameraModel: the image size must be positive");
  }
  camera.width = width;
  camera.height = height;
  // The image spans `height` pixels edge to edge, i.e. height / 2 either side of the centre.
  camera.fy = 0.5 * static_cast<double>(height) / std::tan(0.5 * vertical_fov_rad);
  camera.fx = camera.fy;
  camera.cx = 0.5 * static_cast<double>(width - 1);
  camera.cy = 0.5 * static_cast<double>(height - 1);
}

}  // namespace

CameraModel::CameraModel() {
  set_intrinsics(*this, kDefaultVerticalFovRad, kDefaultWidth, kDefaultHeight);
}

namespace {

// Image "up" is camera -y, so camera +y is the part of -up orthogonal to the view direction z.
Eigen::Vector3d image_down(const Eigen::Vector3d& up, const Eigen::Vector3d& z) {
  return -up + up.dot(z) * z;
}

}  // namespace

LookAtFault look_at_fault(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                          const Eigen::Vector3d& up) {
  const Eigen::Vector3d view = target - eye;
  if (!(view.norm() > 1e-12)) return LookAtFault::kTargetAtEye;
  const Eigen::Vector3d down = image_down(up, view.normalized());
  if (!(down.norm() > 1e-9 * std::max(1.0, up.norm()))) return LookAtFault::kUpAlongView;
  return LookAtFault::kNone;
}

CameraModel CameraModel::look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                                 const Eigen::Vector3d& up, double vertical_fov_rad, int width,
                                 int height) {
  CameraModel camera;
  set_intrinsics(camera, vertical_fov_rad, width, height);

  switch (look_at_fault(eye, target, up)) {
    case LookAtFault::kTargetAtEye:
      throw std::invalid_argument("CameraModel::look_at: eye and target coincide");
    case LookAtFault::kUpAlongView:
      throw std::invalid_argument("CameraModel::look_at: `up` is parallel to the view direction");
    case LookAtFault::kNone:
      break;
  }
  const Eigen::Vector3d z = (target - eye).normalized();
  const Eigen::Vector3d y = image_down(up, z).normalized();
  const Eigen::Vector3d x = y.cross(z);

  camera.world_from_camera.setIdentity();
  camera.world_from_camera.linear().col(0) = x;
  camera.world_from_camera.linear().col(1) = y;
  camera.world_from_camera.linear().col(2) = z;
  camera.world_from_camera.translation() = eye;
  return camera;
}

CameraModel CameraModel::top_down(const Eigen::Vector3d& eye, double vertical_fov_rad, int width,
                                  int height) {
  return look_at(eye, eye - Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(), vertical_fov_rad,
                 width, height);
}

double CameraModel::vertical_fov_rad() const {
  return 2.0 * std::atan(0.5 * static_cast<double>(height) / fy);
}

Eigen::Vector3d CameraModel::to_camera(const Eigen::Vector3d& world) const {
  return world_from_camera.inverse(Eigen::Isometry) * world;
}

std::optional<Eigen::Vector2d> CameraModel::project(const Eigen::Vector3d& world,
                                                    double* depth) const {
  const Eigen::Vector3d p = to_camera(world);
  if (depth != nullptr) *depth = p.z();
  if (!(p.z() > 0.0)) return std::nullopt;
  return Eigen::Vector2d(fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy);
}

Eigen::Vector3d CameraModel::back_project(const Eigen::Vector2d& pixel, double z_depth) const {
  const Eigen::Vector3d p((pixel.x() - cx) * z_depth / fx, (pixel.y() - cy) * z_depth / fy,
                          z_depth);
  return world_from_camera * p;
}

bool CameraModel::in_image(const Eigen::Vector2d& pixel) const {
  return pixel.x() >= -0.5 && pixel.y() >= -0.5 && pixel.x() < static_cast<double>(width) - 0.5 &&
         pixel.y() < static_cast<double>(height) - 0.5;
}

}  // namespace opf::sim
