#pragma once
// Accumulates an estimator's per-frame errors against ground truth over one run and returns the
// paper's "error distance" (mean over frames), overall and over the frames without a measurement,
// with the calibration of the reported covariance, the error against time hidden, reacquisition
// after gaps and the alert's precision and recall (definitions: docs/metrics.md).

#include "opf/core/estimate.h"
#include "opf/core/hidden_error_profile.h"
#include "opf/core/reacquisition.h"

#include <mrpt/poses/CPose3D.h>

#include <cstddef>
#include <map>
#include <string>
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
  /// Calibration over the frames without a measurement (core/calibration.h): the mean NEES over
  /// its dimension, 3 (1 calibrated, below 1 cautious, above 1 over-confident; infinite where a
  /// covariance was singular), and the share of frames inside the 95% ellipsoid. NaN if none.
  double nees_translation = 0.0;
  double nees_rotation = 0.0;
  double inside95_translation = 0.0;
  double inside95_rotation = 0.0;
  ReacquisitionResult reacquisition;
  /// The alert (safety_alert: trace >= epsilon_safe) as a detector of "translation error above
  /// the alert distance", over all frames: precision (NaN without an alert) and recall (NaN
  /// without such a frame).
  double alert_precision = 0.0;
  double alert_recall = 0.0;
  std::vector<HiddenErrorBin> hidden_profile;  ///< means per 0.1 s of time hidden
  std::size_t frames = 0;
  std::size_t unobserved_frames = 0;
};

class ErrorAccumulator {
 public:
  /// The error an alert should announce, m (docs/metrics.md).
  static constexpr double kDefaultAlertDistance = 0.1;

  /// `epsilon_safe`: the feedback module's threshold on every estimate's trace, which raises the
  /// alert. Throws std::invalid_argument unless both are positive and finite.
  explicit ErrorAccumulator(double epsilon_safe, double alert_distance = kDefaultAlertDistance);

  /// One estimate of one object, in time order per object.
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
  double nees_translation_ = 0.0;
  double nees_rotation_ = 0.0;
  std::size_t inside95_translation_ = 0;
  std::size_t inside95_rotation_ = 0;
  double epsilon_safe_;
  double alert_distance_;
  std::size_t alerts_ = 0, large_errors_ = 0, alerts_on_large_errors_ = 0;
  std::map<std::string, double> last_measured_;  ///< per object, s
  HiddenErrorProfile profile_;
  Reacquisition reacquisition_;
  std::size_t frames_ = 0;
  std::size_t unobserved_frames_ = 0;
};

}  // namespace opf
