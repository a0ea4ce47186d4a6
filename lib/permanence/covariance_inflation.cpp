#include "opf/permanence/covariance_inflation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace opf {

void validate(const UncertaintyOptions& options) {
  if (!(options.kappa > 1.0) || !std::isfinite(options.kappa))
    throw std::invalid_argument("uncertainty option kappa must be greater than 1");
  if (!(options.reference_speed > 0.0) || !std::isfinite(options.reference_speed))
    throw std::invalid_argument("uncertainty option reference_speed must be positive");
  if (!(options.reference_period > 0.0) || !std::isfinite(options.reference_period))
    throw std::invalid_argument("uncertainty option reference_period must be positive");
  if (!(options.speed_window >= 0.0))
    throw std::invalid_argument("uncertainty option speed_window must be >= 0");
  if (!(options.max_scale >= 1.0))
    throw std::invalid_argument("uncertainty option max_scale must be at least 1");
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
