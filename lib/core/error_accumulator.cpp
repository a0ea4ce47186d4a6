#include "core/error_accumulator.h"

#include "core/metrics.h"

#include <stdexcept>

namespace opf {

void ErrorAccumulator::add(const Estimate& estimate, const mrpt::poses::CPose3D& truth) {
  const double translation = translation_error(estimate.pose.mean, truth);
  translation_ += translation;
  rotation_paper_ += rotation_error_paper(estimate.pose.mean, truth);
  rotation_geodesic_ += rotation_error_geodesic(estimate.pose.mean, truth);
  ++frames_;
  if (estimate.mode != EstimateMode::kMeasured) {
    translation_unobserved_ += translation;
    ++unobserved_frames_;
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
  r.frames = frames_;
  r.unobserved_frames = unobserved_frames_;
  return r;
}

}  // namespace opf
