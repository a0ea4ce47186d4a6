#include "particles/log_weights.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace opf {

bool LogWeights::normalise() {
  if (log_w_.size() == 0) return true;
  double max_log_w = -std::numeric_limits<double>::infinity();
  bool has_nan = false;
  for (double v : log_w_) {
    if (std::isnan(v)) has_nan = true;
    if (v > max_log_w) max_log_w = v;
  }
  if (has_nan || !std::isfinite(max_log_w)) {
    reset();
    return false;
  }
  // Shift by the max first: the shifted values are small, so subtracting their log-sum keeps full
  // precision (one subtraction of a large log-sum would lose ~1e-13 at log-weights near -2000).
  log_w_.array() -= max_log_w;
  log_w_.array() -= std::log(log_w_.array().exp().sum());
  return true;
}

double LogWeights::effective_sample_fraction() const {
  if (log_w_.size() == 0) return 0.0;
  // Scale by the largest weight first so the ratio is computed without underflow.
  const Eigen::ArrayXd w = (log_w_.array() - log_w_.maxCoeff()).exp();
  const double sum = w.sum();
  return sum * sum / (static_cast<double>(log_w_.size()) * w.square().sum());
}

void LogWeights::reset() {
  log_w_.setConstant(-std::log(static_cast<double>(std::max<Eigen::Index>(log_w_.size(), 1))));
}

}  // namespace opf
