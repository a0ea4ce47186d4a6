#pragma once
// Particle weights kept in the log domain, normalised with log-sum-exp so that products of
// thousands of small likelihoods never underflow.

#include "opf/particles/normalised_weights.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>

namespace opf {

class LogWeights {
 public:
  /// `count` uniform weights.
  explicit LogWeights(std::size_t count = 0) : size_(count) {}

  std::size_t size() const { return size_; }
  /// The log-weights; uniform ones (-log N each) are written out on first access.
  const Eigen::VectorXd& log() const {
    materialise();
    return log_w_;
  }
  /// Write access; the weights are no longer known to be uniform.
  Eigen::VectorXd& log() {
    materialise();
    uniform_ = false;
    ++generation_;
    return log_w_;
  }
  /// Counts the write accesses (log(), for_likelihood(), normalise, reset): what was read from
  /// the weights at one generation still holds while it is the same.
  std::uint64_t generation() const { return generation_; }

  /// Multiplies every weight by its likelihood: adds log-likelihoods.
  void add(const Eigen::VectorXd& log_likelihood) { log() += log_likelihood; }

  /// Storage for a likelihood pass that writes log w_i <- [log w_i +] l_i: returns the array and
  /// sets `accumulate` to whether the current values must be added to. Uniform weights are not
  /// written out first: a constant offset of every log-weight leaves the weights the same.
  double* for_likelihood(bool& accumulate);

  /// Shifts the log-weights so that the linear weights sum to one. Returns false, and resets the
  /// weights to uniform, when no weight is usable (all -inf or NaN): a frame whose likelihood
  /// vanished everywhere must recover, not produce NaN.
  bool normalise();
  /// The same, also writing the normalised linear weights to `linear` (uniform after a reset) and
  /// returning the effective sample fraction the weights had: one pass of exponentials for all
  /// three.
  kernels::NormalisedWeights normalise(Eigen::VectorXd& linear);

  /// Normalised linear weights w_i / sum w (exp(log w) once normalised).
  Eigen::VectorXd linear() const;

  /// Normalised effective sample size (sum w)^2 / (N sum w^2), in (0, 1]; MRPT's convention.
  double effective_sample_fraction() const;

  /// Uniform weights (log w = -log N, so they already sum to one). Their storage is released:
  /// uniform weights need none, and between steps a filter then holds its states alone (which
  /// matters to an ensemble of many filters sharing one cache).
  void reset();
  /// True while the weights are known to be equal (after reset or resampling): statistics can
  /// then skip them.
  bool uniform() const { return uniform_; }

 private:
  void materialise() const;

  std::size_t size_ = 0;
  mutable Eigen::VectorXd log_w_;  ///< empty while uniform and not yet asked for
  bool uniform_ = true;
  std::uint64_t generation_ = 0;
};

}  // namespace opf
