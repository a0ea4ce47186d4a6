#pragma once
// What one normalisation of log-weights found (log_weights.h, and the weight kernels).

namespace opf::kernels {

/// What one normalisation of log-weights found.
struct NormalisedWeights {
  bool usable = true;         ///< false when every weight was -inf or any was NaN
  double ess_fraction = 1.0;  ///< (sum w)^2 / (n sum w^2) of the weights on entry
};

}  // namespace opf::kernels
