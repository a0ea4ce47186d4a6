#pragma once
// Accumulates an estimator's per-frame errors against ground truth over one run and returns the
// paper's "error distance" (mean over frames), overall and over the frames without a measurement.

#include "opf/core/estimate.h"

#include <mrpt/poses/CPose3D.h>

#include <cstddef>
#include <vector>

namespace opf {

struct RunErrors {
  double translation = 0.0;        ///< m, mean over frames
  double rotation_paper = 0.0;     ///< rad, Euler-angle difference norm (paper Sec. IV-A)
  double rotation_geodesic = 0.0;  ///< rad, angle of R_est^T R_true
  /// Mean translation error over the frames whose estimate had no real measurement (0 if none).
  double translation_unobserved = 0.0;
  /// Mean geodesic rotation error over the frames without a measurement (0 if none), rad.
  double rotation_unobserved = 0.0;
  /// Means over the frames with a measurement (0 if none): m and geodesic rad.
  double translation_visible = 0.0;
  double rotation_visible = 0.0;
  /// Honesty of the reported uncertainty over the frames without a measurement: the fraction
  /// whose translation error is within 2 sqrt(trace) of the estimate's position covariance, and
  /// the median of error / sqrt(trace) (0 if none). An honest Gaussian 3-D estimate covers ~99%
  /// with a median ratio ~0.9; a coverage far below means over-confidence, a ratio near 0
  /// useless caution.
  double coverage_unobserved = 0.0;
  double normalised_error_unobserved = 0.0;
  std::size_t frames = 0;
  std::size_t unobserved_frames = 0;
};

class ErrorAccumulator {
 public:
  void add(const Estimate& estimate, const mrpt::poses::CPose3D& truth);
  /// Throws std::logic_error when nothing was added.
  RunErrors result() const;

 private:
  double translation_ = 0.0;
  double rotation_paper_ = 0.0;
  double rotation_geodesic_ = 0.0;
  double translation_unobserved_ = 0.0;
  double rotation_unobserved_ = 0.0;
  double translation_visible_ = 0.0;
  double rotation_visible_ = 0.0;
  std::size_t covered_ = 0;
  std::vector<double> normalised_;  ///< error / sqrt(trace) of each unobserved frame
  std::size_t frames_ = 0;
  std::size_t unobserved_frames_ = 0;
};

}  // namespace opf
