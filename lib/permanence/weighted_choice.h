#pragma once
// A uniform draw mapped to an index in proportion to weights: the inverse of the weights'
// cumulative distribution. A multiple-model particle filter draws each particle's model so (a
// member of motion_model_bank.h at the onset of a gap).

#include <cstddef>
#include <span>

namespace opf {

/// The index i with W_{i-1} <= u W_n < W_i, W_i the sum of the first i + 1 weights (non-negative,
/// not all zero): index i takes the share w_i / W_n of [0, 1). A u outside [0, 1) is clamped to
/// it; a zero weight is never chosen.
std::size_t weighted_choice(std::span<const double> weights, double uniform01);

}  // namespace opf
