#include "opf/permanence/partial_view.h"

#include "opf/core/pose_conversion.h"

namespace opf {

std::optional<Eigen::Vector3d> away_from_cover(const Eigen::Vector3d& position, double extra_noise,
                                               std::string_view object,
                                               const EnsembleView& ensemble,
                                               const OccluderOptions& options) {
  const std::optional<Eigen::Vector3d> ray = line_of_sight(position, options);
  if (!ray || !position.allFinite()) return std::nullopt;
  const double own_radius = stated_radius(ensemble, object);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int covers = 0;
  for (const Estimate& e : ensemble.previous_estimates) {
    if (e.object == object) continue;
    const Eigen::Vector3d offset = position - translation_of(e.pose.mean);
    if (!offset.allFinite() || offset.dot(*ray) <= 0.0) continue;  // not nearer the camera
    const Eigen::Vector3d across = offset - *ray * ray->dot(offset);
    const double d = across.norm();
    const double radius = stated_radius(ensemble, e.object);
    const double overlap = radius > 0.0 && own_radius > 0.0 ? radius + own_radius : options.reach;
    if (d >= overlap) continue;
    ++covers;
    if (d > extra_noise) sum += across / d;
  }
  if (covers == 0 || sum.isZero()) return std::nullopt;
  return sum / covers;
}

PartialViewCentre partial_view_centre(const Eigen::Vector3d& position, double extra_noise,
                                      std::string_view object, const EnsembleView& ensemble,
                                      const OccluderOptions& options) {
  if (!(extra_noise > 0.0)) return {position, 0.0};
  const std::optional<Eigen::Vector3d> away =
      away_from_cover(position, extra_noise, object, ensemble, options);
  if (!away) return {position, 0.0};
  return {position - kPartialViewCentroidShare * extra_noise * *away,
          kPartialViewCentroidShare * away->norm()};
}

}  // namespace opf
