#include "opf/permanence/place_visibility.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace opf {
namespace {

// Phi(margin / sigma): the probability that a Gaussian offset of spread sigma stays within
// `margin` of the edge it is measured from.
double within_margin(double margin, double sigma) {
  return 0.5 * std::erfc(-margin / (sigma * std::sqrt(2.0)));
}

// The spread of `offset` along itself (along the first axis at a zero offset).
double spread_along(const Eigen::VectorXd& offset, const Eigen::MatrixXd& covariance) {
  Eigen::VectorXd along = Eigen::VectorXd::Zero(offset.size());
  along(0) = 1.0;
  if (offset.norm() > 0.0) along = offset / offset.norm();
  return std::sqrt(std::max(along.dot(covariance * along), 1e-18));
}

// G(a) = a Phi(a) + phi(a), the antiderivative of Phi.
double integrated_normal_cdf(double a) {
  return a * 0.5 * std::erfc(-a / std::sqrt(2.0)) +
         std::exp(-0.5 * a * a) * std::numbers::inv_sqrtpi / std::numbers::sqrt2;
}

}  // namespace

double covering_probability(const Eigen::VectorXd& offset, const Eigen::MatrixXd& covariance,
                            double radius) {
  return within_margin(radius - offset.norm(), spread_along(offset, covariance));
}

double covering_probability_of_unknown_radius(const Eigen::VectorXd& offset,
                                              const Eigen::MatrixXd& covariance,
                                              double max_radius) {
  if (!(max_radius > 0.0)) return 0.0;
  const double distance = offset.norm(), sigma = spread_along(offset, covariance);
  return std::clamp(sigma / max_radius *
                        (integrated_normal_cdf((max_radius - distance) / sigma) -
                         integrated_normal_cdf(-distance / sigma)),
                    0.0, 1.0);
}

namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

// The convex hull of the points, counter-clockwise (Andrew's monotone chain).
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (const Eigen::Vector2d& p : points) {  // the lower hull
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i > 0; --i) {  // the upper hull
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.0) --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);  // the last point is the first
  return hull;
}

}  // namespace

double box_covering_probability(const Eigen::MatrixXd& projection, const Eigen::Vector3d& offset,
                                const Eigen::Matrix3d& covariance, const Eigen::Vector3d& box,
                                const Eigen::Quaterniond& orientation) {
  const Eigen::Matrix3d turn = orientation.normalized().toRotationMatrix();
  std::vector<Eigen::Vector2d> corners;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d sign((i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5);
    corners.emplace_back((projection * (turn * sign.cwiseProduct(box))).head<2>());
  }
  const std::vector<Eigen::Vector2d> hull = convex_hull(std::move(corners));
  const Eigen::Vector2d place = (projection * -offset).head<2>();  // from the box's centre
  if (hull.size() < 3) return 0.0;  // a box with no extent across the line of sight
  bool inside = true;
  double nearest = std::numeric_limits<double>::infinity();
  Eigen::Vector2d across = Eigen::Vector2d::UnitX();  // the nearest edge's normal
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d edge = hull[(i + 1) % hull.size()] - a;
    const double along = std::clamp((place - a).dot(edge) / edge.squaredNorm(), 0.0, 1.0);
    const Eigen::Vector2d from_edge = place - (a + along * edge);
    if (cross(a, a + edge, place) < 0.0) inside = false;
    if (from_edge.norm() < nearest) {
      nearest = from_edge.norm();
      across = nearest > 0.0 ? Eigen::Vector2d(from_edge / nearest)
                             : Eigen::Vector2d(edge.y(), -edge.x()).normalized();
    }
  }
  const Eigen::Matrix2d spread =
      (projection * covariance * projection.transpose()).topLeftCorner<2, 2>();
  const double sigma = std::sqrt(std::max(across.dot(spread * across), 1e-18));
  return within_margin(inside ? nearest : -nearest, sigma);
}

Eigen::Matrix3d at_detector_noise(const Eigen::Matrix3d& covariance, double configured, double read,
                                  double process_density, double dt) {
  if (!(read < configured) || !(dt > 0.0) || !covariance.allFinite()) return covariance;
  const double q = process_density * process_density * dt;
  const auto steady = [q](double noise) {
    return 0.5 * (-q + std::sqrt(q * q + 4.0 * q * noise * noise));
  };
  const double floor = steady(read), excess = steady(configured) - floor;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  const Eigen::Vector3d variances = (eigen.eigenvalues().array() - excess).max(floor);
  return eigen.eigenvectors() * variances.asDiagonal() * eigen.eigenvectors().transpose();
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
    if (ray && offset.dot(*ray) > radius) continue;       // behind the place
    const bool box = ray && (b.box.array() > 0.0).all();  // a silhouette in the occlusion plane
    const Eigen::Matrix3d spread = b.carries_the_place ? covariance : covariance + b.covariance;
    seen *= 1.0 - (box ? box_covering_probability(p, offset, spread, b.box, b.orientation)
                       : covering_probability(p * offset, p * spread * p.transpose(), radius));
  }
  return seen;
}

double hiding_radius(const Eigen::Vector3d& place, const Eigen::Vector3d& occluder,
                     const OccluderOptions& options) {
  const Eigen::MatrixXd p = occlusion_plane_projection(place, options);
  return std::min(options.reach, (p * (occluder - place)).norm());
}

}  // namespace opf
