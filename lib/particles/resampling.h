#pragma once
// Resampling: which particles survive and how often. The four schemes of MRPT's
// TParticleResamplingAlgorithm, implemented over our seeded generator (MRPT's own draw from its
// global generator) in O(N), returning indices in increasing order.

#include "opf/core/random.h"
#include "opf/particles/particle_filter_options.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace opf {

/// Indices of `count` particles drawn according to the normalised linear `weights`. Every scheme
/// is unbiased: particle i is copied count * weights[i] times in expectation.
///  - multinomial: independent draws;
///  - stratified: one draw in each of `count` equal strata;
///  - systematic: one draw, shifted by 1/count (copies differ from the expectation by < 1);
///  - residual: floor(count * w) copies, then the remainder multinomially.
std::vector<std::size_t> resample_indices(const Eigen::VectorXd& weights, std::size_t count,
                                          ResamplingScheme scheme, Random& random);

/// Whether to resample now under `options` (every frame, or ESS/N below the threshold).
bool should_resample(const ResamplingOptions& options, double effective_sample_fraction);

}  // namespace opf
