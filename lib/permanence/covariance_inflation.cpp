#include "opf/permanence/covariance_inflation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace opf {

void validate(const UncertaintyOptions& options) {
  check_options(options, "uncertainty");
  const OptionChecker fixed("uncertainty");  // the constants that are not settings
  fixed.number("reference_period", options.reference_period, positive("a positive period (s)"));
  fixed.number("speed_window", options.speed_window, non_negative("seconds >= 0"));
}

CovarianceInflation::CovarianceInflation(const UncertaintyOptions& options) : options_(options) {
  validate(options_);
}

double CovarianceInflation::step(double speed, double dt) {
  const double v = std::max(1.0, speed / options_.reference_speed);
  const double exponent = v * dt / options_.reference_period;
  // Multiply in the log domain: kappa^exponent can overflow on its own for a huge speed.
  const double log_scale = std::log(scale_) + exponent * std::log(options_.kappa);
  if (log_scale >= std::log(options_.max_scale)) {
    scale_ = options_.max_scale;
    capped_ = true;
  } else {
    scale_ = std::exp(log_scale);
  }
  return scale_;
}

}  // namespace opf
