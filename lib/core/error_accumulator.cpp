#include "opf/core/error_accumulator.h"

#include "opf/core/metrics.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace opf {

void ErrorAccumulator::add(const Estimate& estimate, const mrpt::poses::CPose3D& truth) {
  const double translation = translation_error(estimate.pose.mean, truth);
  const double geodesic = rotation_error_geodesic(estimate.pose.mean, truth);
  translation_ += translation;
  rotation_paper_ += rotation_error_paper(estimate.pose.mean, truth);
  rotation_geodesic_ += geodesic;
  ++frames_;
  if (estimate.mode != EstimateMode::kMeasured) {
    translation_unobserved_ += translation;
    rotation_unobserved_ += geodesic;
    ++unobserved_frames_;
    const double spread = std::sqrt(estimate.pose.cov.asEigen().topLeftCorner<3, 3>().trace());
    if (translation <= 2.0 * spread) ++covered_;
    normalised_.push_back(spread > 0.0 ? translation / spread
                                       : std::numeric_limits<double>::infinity());
  } else {
    translation_visible_ += translation;
    rotation_visible_ += geodesic;
  }
}

RunErrors ErrorAccumulator::result() const {
  if (frames_ == 0) throw std::logic_error("ErrorAccumulator: no frames");
  const auto n = static_cast<double>(frames_);
  RunErrors r;
  r.translation = translation_ / n;
  r.rotation_paper = rotation_paper_ / n;
  r.rotation_geodesic = rotation_geodesic_ / n;
  r.translation_unobserved =
      unobserved_frames_ ? translation_unobserved_ / static_cast<double>(unobserved_frames_) : 0.0;
  const std::size_t visible = frames_ - unobserved_frames_;
  if (visible) {
    r.translation_visible = translation_visible_ / static_cast<double>(visible);
    r.rotation_visible = rotation_visible_ / static_cast<double>(visible);
  }
  if (unobserved_frames_) {
    const auto hidden = static_cast<double>(unobserved_frames_);
    r.rotation_unobserved = rotation_unobserved_ / hidden;
    r.coverage_unobserved = static_cast<double>(covered_) / hidden;
    std::vector<double> sorted = normalised_;
    const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
    std::nth_element(sorted.begin(), middle, sorted.end());
    r.normalised_error_unobserved = *middle;
  }
  r.frames = frames_;
  r.unobserved_frames = unobserved_frames_;
  return r;
}

}  // namespace opf
