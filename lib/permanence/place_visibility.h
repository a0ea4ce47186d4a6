#pragma once
// Whether the camera would see a hidden object where a hypothesis puts it: the negative
// information that weighs the occluder module's hypotheses (carried or left). A place is in view
// when its centre is clear of every other tracked object's silhouette: each covers it with the
// probability that its centre lies within its radius of the place's line of sight; the objects
// cover it independently.

#include "opf/permanence/occluder_selection.h"

#include <Eigen/Core>

#include <span>

namespace opf {

/// P(|x| <= radius) for x ~ N(offset, covariance) in the occlusion plane, to first order: the
/// disc's edge taken as straight where it is nearest the offset, Phi((radius - |m|) / sigma)
/// with sigma the spread along m. At a zero offset, the spread along the first axis.
double covering_probability(const Eigen::VectorXd& offset, const Eigen::MatrixXd& covariance,
                            double radius);

/// Another tracked object's position estimate, as something that may stand in the way.
struct ViewBlocker {
  Eigen::Vector3d mean;
  Eigen::Matrix3d covariance;
  /// m: its silhouette's radius as its detector states it (Detection::radius); 0: not stated.
  double radius = 0.0;
};

/// The probability that the camera sees a place (a position estimate `place` +- `covariance`):
/// that no blocker covers it, each covering it when its centre lies within its radius (m;
/// `fallback_radius` for a blocker whose detector states none) of the place's line of sight
/// (options.plane) and no more than that radius behind it along the ray: prod_k (1 - P_k), the
/// objects covering independently. A blocker whose estimate is not finite is passed over.
double seen_probability(const Eigen::Vector3d& place, const Eigen::Matrix3d& covariance,
                        std::span<const ViewBlocker> blockers, double fallback_radius,
                        const OccluderOptions& options);

/// m: how near an occluder's centre was to a place across the line of sight (options.plane) when
/// it last let it be seen, at most `options.reach`: any tracked object nearer covers the place.
double hiding_radius(const Eigen::Vector3d& place, const Eigen::Vector3d& occluder,
                     const OccluderOptions& options);

}  // namespace opf
