#pragma once
// The uncertainty module (paper Sec. III-B.3, Eq. 14): while the measurement is missing the
// observation covariance grows as Q~_k = alpha_k Q~_{k-1}, alpha_k = kappa^v, and returns to Q
// when a real measurement arrives.

#include "opf/core/option_schema.h"

namespace opf {

/// How v is measured (the paper leaves it open): v = max(1, speed / reference_speed), where speed
/// is that of the virtual measurement (the fitted trajectory's, or the occluder's), so a hidden
/// object grows at least kappa per reference frame even when still (the paper's trace curves grow
/// for the static hidden ball too) and faster the faster it is carried. The exponent is scaled by
/// dt / reference_period so the growth per second does not depend on the frame rate.
struct UncertaintyOptions {
  double kappa = 1.03;                   ///< paper Sec. III-B.3
  double reference_speed = 0.1;          ///< m/s: speed at which v = 1
  double reference_period = 1.0 / 30.0;  ///< s: the paper's camera frame period
  /// s: an occluder's speed is its estimate's displacement over this window divided by the time,
  /// so the frame-to-frame jitter of a still occluder's estimate does not read as speed.
  double speed_window = 0.2;
  /// Q~ stops growing at this multiple of Q (reported via capped()) so a long occlusion stays
  /// finite instead of overflowing.
  double max_scale = 1e6;
};

/// The settings file's `opf.uncertainty:` section (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, UncertaintyOptions& o) {
  v.number("kappa", o.kappa, greater_than(1.0, "a number kappa > 1"));
  v.number("reference_speed", o.reference_speed, positive("a positive speed (m/s)"));
  // reference_period (the paper's 30 Hz) and speed_window are stated constants, not settings.
  v.number("max_scale", o.max_scale, at_least(1.0, "a number >= 1"));
}

class CovarianceInflation {
 public:
  explicit CovarianceInflation(const UncertaintyOptions& options);

  /// Back to Q (a real measurement arrived).
  void reset() {
    scale_ = 1.0;
    capped_ = false;
  }
  /// One missing-measurement step of `dt` seconds at the given speed; returns the new scale.
  double step(double speed, double dt);

  /// alpha-product so far: Q~ = scale() * Q.
  double scale() const { return scale_; }
  bool capped() const { return capped_; }

 private:
  UncertaintyOptions options_;
  double scale_ = 1.0;
  bool capped_ = false;
};

/// Throws std::invalid_argument naming the first option out of range (kappa <= 1, ...).
void validate(const UncertaintyOptions& options);

}  // namespace opf
