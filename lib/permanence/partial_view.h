#pragma once
// Where a partly covered object's centre lies, given its detection. A detector that reports the
// centroid of what it sees is off towards the visible part: for a disc covered by a straight edge
// with visible share f, by 0.85-0.93 of (1 - f) r from the centre (r its radius), away from the
// edge. A detection that states its extra noise e = (1 - f) r (Detection::extra_noise) is
// corrected by kPartialViewCentroidShare e away from the tracked objects that cover it; the rest
// of the offset stays unknown, shared by a stretch of partial views (motion_model_bank.h).

#include "opf/core/estimator.h"
#include "opf/permanence/occluder_selection.h"

#include <Eigen/Core>

#include <optional>
#include <string_view>

namespace opf {

/// The centroid's offset from the centre of a disc under a straight edge, in units of (1 - f) r:
/// 0.85-0.93 for every visible share f from 0.05 to 0.95.
inline constexpr double kPartialViewCentroidShare = 0.87;

/// Where a partial view's visible part lies from its centre, across the line of sight: the mean of
/// the unit directions away from each tracked object (other than `object`) that covers it, a
/// vector of length at most 1 (covers on opposite sides cancel). A cover is nearer the camera than
/// `position` and overlaps it across the line of sight: its centre within the two stated radii
/// summed (as the detections last stated them: EnsembleView::stated_radii), or within options.reach
/// where either states none. A cover whose centre is within `extra_noise` (m) of `position` leaves
/// a ring in view and counts as no direction. None without a cover, or without a line of sight
/// (plane 3d).
std::optional<Eigen::Vector3d> away_from_cover(const Eigen::Vector3d& position, double extra_noise,
                                               std::string_view object,
                                               const EnsembleView& ensemble,
                                               const OccluderOptions& options);

/// A detection with the known part of its partial view's offset taken off.
struct PartialViewCentre {
  Eigen::Vector3d position;
  /// The share of the stated extra noise taken off: kPartialViewCentroidShare |away_from_cover|,
  /// 0 when none was; the offset's rest has variance (1 - share^2) extra_noise^2.
  double known_share = 0.0;
};

/// position - kPartialViewCentroidShare extra_noise away_from_cover(...), or the position itself.
PartialViewCentre partial_view_centre(const Eigen::Vector3d& position, double extra_noise,
                                      std::string_view object, const EnsembleView& ensemble,
                                      const OccluderOptions& options);

}  // namespace opf
