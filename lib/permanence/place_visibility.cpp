#include "opf/permanence/place_visibility.h"

#include <algorithm>
#include <cmath>

namespace opf {

double covering_probability(const Eigen::VectorXd& offset, const Eigen::MatrixXd& covariance,
                            double radius) {
  const double distance = offset.norm();
  Eigen::VectorXd along = Eigen::VectorXd::Zero(offset.size());
  along(0) = 1.0;
  if (distance > 0.0) along = offset / distance;
  const double sigma = std::sqrt(std::max(along.dot(covariance * along), 1e-18));
  return 0.5 * std::erfc(-(radius - distance) / (sigma * std::sqrt(2.0)));
}

double seen_probability(const Eigen::Vector3d& place, const Eigen::Matrix3d& covariance,
                        std::span<const ViewBlocker> blockers, double fallback_radius,
                        const OccluderOptions& options) {
  const Eigen::MatrixXd p = occlusion_plane_projection(place, options);
  const std::optional<Eigen::Vector3d> ray = line_of_sight(place, options);
  double seen = 1.0;
  for (const ViewBlocker& b : blockers) {
    if (!b.mean.allFinite() || !b.covariance.allFinite()) continue;
    const double radius = b.radius > 0.0 ? b.radius : fallback_radius;
    const Eigen::Vector3d offset = b.mean - place;
    if (ray && offset.dot(*ray) > radius) continue;  // behind the place
    seen *= 1.0 - covering_probability(p * offset, p * (covariance + b.covariance) * p.transpose(),
                                       radius);
  }
  return seen;
}

double hiding_radius(const Eigen::Vector3d& place, const Eigen::Vector3d& occluder,
                     const OccluderOptions& options) {
  const Eigen::MatrixXd p = occlusion_plane_projection(place, options);
  return std::min(options.reach, (p * (occluder - place)).norm());
}

}  // namespace opf
