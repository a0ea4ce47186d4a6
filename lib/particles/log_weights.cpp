#include "opf/particles/log_weights.h"

#include "opf/particles/weight_kernels.h"

#include <algorithm>
#include <cmath>

namespace opf {

bool LogWeights::normalise() {
  Eigen::VectorXd linear;
  return normalise(linear).usable;
}

kernels::NormalisedWeights LogWeights::normalise(Eigen::VectorXd& linear) {
  materialise();
  ++generation_;
  linear.resize(log_w_.size());
  const kernels::NormalisedWeights result =
      kernels::normalise_log_weights(log_w_.data(), linear.data(), size());
  if (!result.usable) {
    reset();
    linear.setConstant(1.0 / static_cast<double>(std::max<std::size_t>(size(), 1)));
  }
  return result;
}

Eigen::VectorXd LogWeights::linear() const {
  materialise();
  Eigen::VectorXd w(log_w_.size());
  const double sum = kernels::relative_weights(log_w_.data(), w.data(), size());
  return w / sum;
}

double LogWeights::effective_sample_fraction() const {
  if (size_ == 0) return 0.0;
  if (uniform_) return 1.0;
  materialise();
  // Relative to the largest weight, so the ratio is computed without underflow.
  Eigen::VectorXd w(log_w_.size());
  const double sum = kernels::relative_weights(log_w_.data(), w.data(), size());
  return sum * sum / (static_cast<double>(log_w_.size()) * w.squaredNorm());
}

double* LogWeights::for_likelihood(bool& accumulate) {
  accumulate = !uniform_;
  ++generation_;
  if (uniform_) log_w_.resize(Eigen::Index(size_));  // about to be overwritten
  uniform_ = false;
  return log_w_.data();
}

void LogWeights::reset() {
  ++generation_;
  log_w_ = Eigen::VectorXd();
  uniform_ = true;
}

void LogWeights::materialise() const {
  if (static_cast<std::size_t>(log_w_.size()) == size_) return;
  log_w_.setConstant(Eigen::Index(size_),
                     -std::log(static_cast<double>(std::max<std::size_t>(size_, 1))));
}

}  // namespace opf
