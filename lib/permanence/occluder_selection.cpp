#include "opf/permanence/occluder_selection.h"

#include "opf/permanence/bhattacharyya.h"
#include "opf/permanence/place_visibility.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

// The gate: a candidate at `offset` from the hidden object can hide it only if its centre lies
// within its reach plus gate_sigmas of their combined spread (`spread`, in the occlusion plane)
// across the line of sight, and at most `reach` behind the object along it.
bool within_gate(const Eigen::Vector3d& offset, const Eigen::MatrixXd& projection,
                 const Eigen::MatrixXd& spread, double reach,
                 const std::optional<Eigen::Vector3d>& ray, const OccluderOptions& options) {
  const double sigma = std::sqrt(
      std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(spread, Eigen::EigenvaluesOnly)
                        .eigenvalues()
                        .maxCoeff()));
  const bool across = (projection * offset).norm() <= reach + options.gate_sigmas * sigma;
  const bool in_front = !ray || offset.dot(*ray) <= options.reach;
  return across && in_front;
}

// How probably a candidate `across` from the hidden object (in the occlusion plane, `spread`
// their combined covariance) hides it: within its stated radius, or, of no stated size, within a
// reach anywhere up to options.reach, no extent more likely.
double hiding_probability(const Eigen::VectorXd& across, const Eigen::MatrixXd& spread,
                          double radius, const OccluderOptions& options) {
  return radius > 0.0 ? covering_probability(across, spread, radius)
                      : covering_probability_of_unknown_radius(across, spread, options.reach);
}

}  // namespace

std::optional<Eigen::Vector3d> line_of_sight(const Eigen::Vector3d& hidden_mean,
                                             const OccluderOptions& options) {
  if (options.plane == OccluderPlane::k3D) return std::nullopt;
  if (options.plane == OccluderPlane::kLineOfSight && !options.camera_position)
    throw std::invalid_argument(
        "occluder plane line_of_sight needs the camera's position (or plane auto)");
  Eigen::Vector3d ray(0, 0, -1);
  if (options.plane != OccluderPlane::kXY && options.camera_position) {
    const Eigen::Vector4d& camera = *options.camera_position;
    // A camera at infinity (w = 0) sees every point along the same ray.
    const Eigen::Vector3d to_object = camera.w() == 0.0
                                          ? Eigen::Vector3d(-camera.head<3>())
                                          : Eigen::Vector3d(hidden_mean - camera.hnormalized());
    if (to_object.norm() > 1e-9) ray = to_object.normalized();
  }
  return ray;
}

Eigen::MatrixXd occlusion_plane_projection(const Eigen::Vector3d& hidden_mean,
                                           const OccluderOptions& options) {
  const std::optional<Eigen::Vector3d> sight = line_of_sight(hidden_mean, options);
  if (!sight) return Eigen::Matrix3d::Identity();
  const Eigen::Vector3d ray = *sight;
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

std::vector<WeightedOccluder> probable_occluders(const OccluderChoice& choice, double floor,
                                                 std::size_t max_count) {
  // Most probable first; probabilities equal to 10^-6 (two candidates that both surely cover the
  // object) keep the nearer by D_B first, the paper's choice.
  std::vector<WeightedOccluder> kept = choice.weighted;
  const auto rounded = [](const WeightedOccluder& w) { return std::round(w.probability * 1e6); };
  std::stable_sort(kept.begin(), kept.end(),
                   [&](const auto& a, const auto& b) { return rounded(a) > rounded(b); });
  std::size_t count = 0;
  while (count < kept.size() && count < std::max<std::size_t>(max_count, 1) &&
         (count == 0 || kept[count].probability >= floor))
    ++count;
  kept.resize(count);
  double total = 0.0;
  for (const WeightedOccluder& w : kept) total += w.probability;
  for (WeightedOccluder& w : kept) w.probability = total > 0.0 ? w.probability / total : 1.0;
  return kept;
}

OccluderChoice choose_occluders(const Eigen::Vector3d& hidden_mean,
                                const Eigen::Matrix3d& hidden_covariance,
                                std::span<const OccluderCandidate> candidates,
                                const OccluderOptions& options) {
  OccluderChoice choice;
  choice.second_distance = std::numeric_limits<double>::infinity();
  if (candidates.empty() || !hidden_mean.allFinite() || !hidden_covariance.allFinite())
    return choice;
  const Eigen::MatrixXd p = occlusion_plane_projection(hidden_mean, options);
  const Eigen::VectorXd hidden_mu = p * hidden_mean;
  const Eigen::MatrixXd hidden_sigma = p * hidden_covariance * p.transpose();

  const std::optional<Eigen::Vector3d> ray = line_of_sight(hidden_mean, options);

  std::vector<std::pair<double, WeightedOccluder>> weighted;  // (D_B, candidate)
  std::size_t best = 0, runner_up = 0, plausible = 0;
  double best_d = std::numeric_limits<double>::infinity();
  double runner_up_d = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < candidates.size(); ++j) {
    const OccluderCandidate& c = candidates[j];
    if (!c.mean.allFinite() || !c.covariance.allFinite()) continue;
    const Eigen::MatrixXd sigma = p * c.covariance * p.transpose();
    // It hides the object within its own silhouette where its size is stated.
    const double reach = c.radius > 0.0 ? c.radius : options.reach;
    if (options.gate &&
        !within_gate(c.mean - hidden_mean, p, hidden_sigma + sigma, reach, ray, options)) {
      ++choice.implausible;
      continue;
    }
    double d = std::numeric_limits<double>::infinity();
    try {
      d = bhattacharyya_distance(hidden_mu, hidden_sigma, p * c.mean, sigma);
    } catch (const std::invalid_argument&) {
      continue;  // a degenerate cloud (zero or non-finite spread): not a usable occluder
    }
    if (!std::isfinite(d)) continue;
    ++plausible;
    if (options.gate)
      weighted.push_back({d,
                          {j, hiding_probability(p * (c.mean - hidden_mean), hidden_sigma + sigma,
                                                 c.radius, options)}});
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
  if (plausible == 0) return choice;
  std::stable_sort(weighted.begin(), weighted.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  double total = 0.0;
  for (const auto& w : weighted) total += w.second.probability;
  for (const auto& w : weighted)
    choice.weighted.push_back({w.second.candidate, total > 0.0 ? w.second.probability / total
                                                               : 1.0 / double(weighted.size())});
  choice.nearest = best;
  choice.nearest_distance = best_d;
  choice.second_distance = runner_up_d;
  choice.nearest_offset = (p * (candidates[best].mean - hidden_mean)).norm();
  if (plausible < 2) return choice;
  choice.second_offset = (p * (candidates[runner_up].mean - hidden_mean)).norm();
  // The tie in metres, as the paper sets epsilon_occ "based on the size of the tested object": a
  // gap of D_B would be a unitless number that the estimates' jitter alone always exceeds.
  if (std::abs(choice.second_offset - choice.nearest_offset) <= options.epsilon_occ)
    choice.second = runner_up;
  return choice;
}

}  // namespace opf
