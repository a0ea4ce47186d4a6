#include "permanence/occluder_selection.h"

#include "permanence/bhattacharyya.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <vector>

namespace opf {

Eigen::MatrixXd occlusion_plane_projection(const Eigen::Vector3d& hidden_mean,
                                           const OccluderOptions& options) {
  if (options.plane == OccluderPlane::k3D) return Eigen::Matrix3d::Identity();
  Eigen::Vector3d ray(0, 0, -1);
  if (options.plane == OccluderPlane::kLineOfSight && options.camera_position) {
    const Eigen::Vector3d to_object = hidden_mean - *options.camera_position;
    if (to_object.norm() > 1e-9) ray = to_object.normalized();
  }
  // An orthonormal basis of the plane perpendicular to the ray; for the top-down ray it is x, y.
  Eigen::Vector3d u = ray.unitOrthogonal();
  if (std::abs(ray.z()) > 0.999) u = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d v = ray.cross(u).normalized();
  u = v.cross(ray).normalized();
  Eigen::MatrixXd projection(2, 3);
  projection.row(0) = u.transpose();
  projection.row(1) = v.transpose();
  return projection;
}

OccluderChoice choose_occluders(const Eigen::Vector3d& hidden_mean,
                                const Eigen::Matrix3d& hidden_covariance,
                                std::span<const OccluderCandidate> candidates,
                                const OccluderOptions& options) {
  OccluderChoice choice;
  choice.second_distance = std::numeric_limits<double>::infinity();
  if (candidates.empty()) return choice;
  const Eigen::MatrixXd p = occlusion_plane_projection(hidden_mean, options);
  const Eigen::VectorXd hidden_mu = p * hidden_mean;
  const Eigen::MatrixXd hidden_sigma = p * hidden_covariance * p.transpose();

  std::size_t best = 0, runner_up = 0;
  double best_d = std::numeric_limits<double>::infinity();
  double runner_up_d = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < candidates.size(); ++j) {
    const double d = bhattacharyya_distance(hidden_mu, hidden_sigma, p * candidates[j].mean,
                                            p * candidates[j].covariance * p.transpose());
    if (d < best_d) {
      runner_up = best;
      runner_up_d = best_d;
      best = j;
      best_d = d;
    } else if (d < runner_up_d) {
      runner_up = j;
      runner_up_d = d;
    }
  }
  choice.nearest = best;
  choice.nearest_distance = best_d;
  choice.second_distance = runner_up_d;
  if (candidates.size() > 1 && runner_up_d - best_d <= options.epsilon_occ)
    choice.second = runner_up;
  return choice;
}

}  // namespace opf
