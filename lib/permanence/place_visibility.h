#pragma once
// Whether the camera would see a hidden object where a hypothesis puts it: the negative
// information that weighs the occluder module's hypotheses (carried or left). A place is in view
// when its centre is clear of every other tracked object's silhouette: each covers it with the
// probability that the place's line of sight passes through it (within its radius of its centre,
// or through the box its detector states), given where both are; the objects cover it
// independently.

#include "opf/permanence/occluder_selection.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <span>

namespace opf {

/// P(|x| <= radius) for x ~ N(offset, covariance) in the occlusion plane, to first order: the
/// disc's edge taken as straight where it is nearest the offset, Phi((radius - |m|) / sigma)
/// with sigma the spread along m. At a zero offset, the spread along the first axis.
double covering_probability(const Eigen::VectorXd& offset, const Eigen::MatrixXd& covariance,
                            double radius);

/// P(|x| <= rho) as covering_probability, for a radius rho unknown and uniform on
/// [0, max_radius] (a cover whose size no detector states): the mean of Phi((rho - |m|) / sigma)
/// over rho, (sigma / R) [G((R - |m|) / sigma) - G(-|m| / sigma)] with G(a) = a Phi(a) + phi(a),
/// R the max_radius. A max_radius of 0: 0.
double covering_probability_of_unknown_radius(const Eigen::VectorXd& offset,
                                              const Eigen::MatrixXd& covariance, double max_radius);

/// P(the place lies within a box's silhouette) for the box's centre at `offset` from the place
/// +- `covariance` (their combined spread, m^2): the box (full extents `box`, m, in its own frame,
/// turned by `orientation`) projected by `projection` onto the occlusion plane, a convex polygon;
/// to first order, as for the disc, Phi(d / sigma) with d the place's signed distance inside the
/// polygon's nearest edge and sigma the spread across that edge.
double box_covering_probability(const Eigen::MatrixXd& projection, const Eigen::Vector3d& offset,
                                const Eigen::Matrix3d& covariance, const Eigen::Vector3d& box,
                                const Eigen::Quaterniond& orientation);

/// A position covariance at the detector's own noise. A filter's covariance is computed with its
/// configured observation noise `configured` (m); the detector's, read from its detections
/// (DetectorJitter), is `read`. For a measured object the particle filter's covariance is the
/// steady state of its random walk (density `process_density`, m/sqrt(s)) observed every `dt`
/// s with noise n, P(n) = (-q + sqrt(q^2 + 4 q n^2)) / 2 per axis with q = process_density^2 dt;
/// the excess P(configured) - P(read) is taken off each eigenvalue, none below P(read). What a
/// hidden object's covariance has grown by stays. `read` at or above `configured`: unchanged.
Eigen::Matrix3d at_detector_noise(const Eigen::Matrix3d& covariance, double configured, double read,
                                  double process_density, double dt);

/// Another tracked object's position estimate, as something that may stand in the way.
struct ViewBlocker {
  Eigen::Vector3d mean;
  Eigen::Matrix3d covariance;
  /// m: its silhouette's radius as its detector states it (Detection::radius); 0: not stated.
  double radius = 0.0;
  /// m: the full extents of its bounding box in its own frame as its detector states them
  /// (Detection::box); zero: not stated. Where stated, its silhouette is the box's, turned by
  /// `orientation`, in place of the radius's disc.
  Eigen::Vector3d box = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  /// The place is carried by this object (the hypothesis being weighed is that the object moves
  /// with it): it covers the place as far as their offset says, the place's own spread about it,
  /// wherever the carrier itself is; its own covariance does not enter.
  bool carries_the_place = false;
};

/// The probability that the camera sees a place (a position estimate `place` +- `covariance`):
/// that no blocker covers it, each covering it when the place's line of sight passes through its
/// stated box, or else when its centre lies within its radius (m; `fallback_radius` for a blocker
/// whose detector states neither) of the place's line of sight
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
