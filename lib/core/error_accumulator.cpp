#include "opf/core/error_accumulator.h"

#include "opf/core/calibration.h"
#include "opf/core/metrics.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace opf {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double ratio_or_nan(std::size_t numerator, std::size_t denominator) {
  return denominator ? static_cast<double>(numerator) / static_cast<double>(denominator) : kNaN;
}

}  // namespace

ErrorAccumulator::ErrorAccumulator(double epsilon_safe, double alert_distance)
    : epsilon_safe_(epsilon_safe), alert_distance_(alert_distance) {
  if (!(epsilon_safe > 0.0) || !std::isfinite(epsilon_safe))
    throw std::invalid_argument("ErrorAccumulator: epsilon_safe must be positive");
  if (!(alert_distance > 0.0) || !std::isfinite(alert_distance))
    throw std::invalid_argument("ErrorAccumulator: the alert distance must be positive (m)");
}

void ErrorAccumulator::add(const Estimate& estimate, const mrpt::poses::CPose3D& truth) {
  const double translation = translation_error(estimate.pose.mean, truth);
  const double geodesic = rotation_error_geodesic(estimate.pose.mean, truth);
  translation_ += translation;
  rotation_paper_ += rotation_error_paper(estimate.pose.mean, truth);
  rotation_geodesic_ += geodesic;
  ++frames_;
  const bool large = translation > alert_distance_;
  large_errors_ += large;
  const bool alert = safety_alert(estimate, epsilon_safe_);
  alerts_ += alert;
  alerts_on_large_errors_ += large && alert;
  const bool measured = estimate.mode == EstimateMode::kMeasured;
  reacquisition_.add(estimate.object, measured, translation);
  if (measured) {
    translation_visible_ += translation;
    rotation_visible_ += geodesic;
    last_measured_[estimate.object] = estimate.t;
    return;
  }
  translation_unobserved_ += translation;
  rotation_unobserved_ += geodesic;
  ++unobserved_frames_;
  const double spread = std::sqrt(estimate.pose.cov.asEigen().topLeftCorner<3, 3>().trace());
  if (translation <= 2.0 * spread) ++covered_;
  normalised_.push_back(spread > 0.0 ? translation / spread
                                     : std::numeric_limits<double>::infinity());
  const double nees_t = translation_nees(estimate, truth);
  const double nees_r = rotation_nees(estimate, truth);
  nees_translation_ += nees_t;
  nees_rotation_ += nees_r;
  inside95_translation_ += nees_t <= kChiSquare3Dof95;
  inside95_rotation_ += nees_r <= kChiSquare3Dof95;
  // An estimate starts at a detection, so every hidden frame follows a measured one.
  const auto last = last_measured_.find(estimate.object);
  if (last != last_measured_.end() && estimate.t > last->second)
    profile_.add(estimate.t - last->second, translation, geodesic);
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
  r.nees_translation = r.nees_rotation = kNaN;
  r.inside95_translation = ratio_or_nan(inside95_translation_, unobserved_frames_);
  r.inside95_rotation = ratio_or_nan(inside95_rotation_, unobserved_frames_);
  r.alert_precision = ratio_or_nan(alerts_on_large_errors_, alerts_);
  r.alert_recall = ratio_or_nan(alerts_on_large_errors_, large_errors_);
  r.reacquisition = reacquisition_.result();
  r.hidden_profile = profile_.means();
  if (unobserved_frames_) {
    const auto hidden = static_cast<double>(unobserved_frames_);
    r.nees_translation = nees_translation_ / (3.0 * hidden);
    r.nees_rotation = nees_rotation_ / (3.0 * hidden);
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
