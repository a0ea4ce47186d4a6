#pragma once
// Particle weights kept in the log domain, normalised with log-sum-exp so that products of
// thousands of small likelihoods never underflow.

#include <Eigen/Core>

#include <cstddef>

namespace opf {

class LogWeights {
 public:
  explicit LogWeights(std::size_t count = 0) : log_w_(Eigen::VectorXd::Zero(Eigen::Index(count))) {}

  std::size_t size() const { return static_cast<std::size_t>(log_w_.size()); }
  const Eigen::VectorXd& log() const { return log_w_; }
  Eigen::VectorXd& log() { return log_w_; }

  /// Multiplies every weight by its likelihood: adds log-likelihoods.
  void add(const Eigen::VectorXd& log_likelihood) { log_w_ += log_likelihood; }

  /// Shifts the log-weights so that the linear weights sum to one. Returns false, and resets the
  /// weights to uniform, when no weight is usable (all -inf or NaN): a frame whose likelihood
  /// vanished everywhere must recover, not produce NaN.
  bool normalise();

  /// Linear weights exp(log w); they sum to one after normalise().
  Eigen::VectorXd linear() const { return log_w_.array().exp(); }

  /// Normalised effective sample size (sum w)^2 / (N sum w^2), in (0, 1]; MRPT's convention.
  double effective_sample_fraction() const;

  /// Uniform weights (log w = -log N, so they already sum to one).
  void reset();

 private:
  Eigen::VectorXd log_w_;
};

}  // namespace opf
