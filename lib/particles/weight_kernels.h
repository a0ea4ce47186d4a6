#pragma once
// The particle kernels of the weights (log_weights.h, pose_particle_filter.cpp): normalisation
// and relative weights.
// Private to lib/particles (not installed): a portion of n particles of dimension D is D
// contiguous rows of n values (x..., y..., z... in double for translation; x..., y..., z..., w...
// in float for rotation quaternions), and each kernel is one pass that vectorises, compiled for
// the CPU at hand (kernel_dispatch.h).

#include "opf/particles/normalised_weights.h"

#include <array>
#include <cstddef>

namespace opf::kernels {

/// Shifts log_w so that exp(log_w) sums to one and writes those linear weights to `linear`, in
/// one pass of exponentials. When no weight is usable, returns usable = false and leaves both
/// arrays untouched.
NormalisedWeights normalise_log_weights(double* log_w, double* linear, std::size_t n);

/// Relative weights for resampling right away: linear[i] = exp(log_w[i] - max log_w) in single
/// precision (a weight below e^-87 of the largest is 0), and the ESS fraction. log_w is left as
/// it is (resampling makes it uniform). usable = false when every weight was -inf or any NaN.
NormalisedWeights resampling_weights(const double* log_w, float* linear, std::size_t n);

/// linear[i] = exp(log_w[i] - max log_w) (unnormalised, largest 1); returns their sum.
double relative_weights(const double* log_w, double* linear, std::size_t n);

}  // namespace opf::kernels
