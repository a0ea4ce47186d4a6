#include "opf/particles/resampling.h"

#include "opf/particles/resampling_kernels.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace opf {
namespace {

// Walks the cumulative weights once for sorted positions u (in [0, 1)).
template <class Positions>
std::vector<std::size_t> walk_cdf(const Eigen::VectorXd& weights, std::size_t count,
                                  Positions&& position_of) {
  std::vector<std::size_t> indices(count);
  const std::size_t last = static_cast<std::size_t>(weights.size()) - 1;
  std::size_t j = 0;
  double cumulative = weights[0];
  for (std::size_t k = 0; k < count; ++k) {
    const double u = position_of(k);
    // Rounding can leave the total a hair below u near 1: the last particle takes the remainder.
    while (u >= cumulative && j < last) cumulative += weights[Eigen::Index(++j)];
    indices[k] = j;
  }
  return indices;
}

// `count` sorted uniforms in [0, 1) in O(N): normalised partial sums of exponential spacings.
std::vector<double> sorted_uniforms(std::size_t count, Random& random) {
  std::vector<double> sums(count);
  double total = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    total += -std::log(1.0 - random.uniform());
    sums[k] = total;
  }
  total += -std::log(1.0 - random.uniform());
  for (double& s : sums) s /= total;
  return sums;
}

std::vector<std::size_t> multinomial(const Eigen::VectorXd& weights, std::size_t count,
                                     Random& random) {
  const std::vector<double> u = sorted_uniforms(count, random);
  return walk_cdf(weights, count, [&](std::size_t k) { return u[k]; });
}

}  // namespace

std::vector<std::size_t> resample_indices(const Eigen::VectorXd& weights, std::size_t count,
                                          ResamplingScheme scheme, Random& random) {
  if (weights.size() == 0) throw std::invalid_argument("resample_indices: no particles");
  if (count == 0) return {};
  const double n = static_cast<double>(count);
  switch (scheme) {
    case mrpt::bayes::CParticleFilter::prMultinomial:
      return multinomial(weights, count, random);
    case mrpt::bayes::CParticleFilter::prStratified: {
      std::vector<double> uniforms(count);
      for (double& u : uniforms) u = random.uniform();
      std::vector<std::size_t> indices(count);
      kernels::stratified_indices(weights.data(), static_cast<std::size_t>(weights.size()),
                                  uniforms.data(), count, indices.data());
      return indices;
    }
    case mrpt::bayes::CParticleFilter::prSystematic: {
      std::vector<std::size_t> indices(count);
      kernels::systematic_indices(weights.data(), static_cast<std::size_t>(weights.size()),
                                  random.uniform(), count, indices.data());
      return indices;
    }
    case mrpt::bayes::CParticleFilter::prResidual: {
      std::vector<std::size_t> indices;
      indices.reserve(count);
      Eigen::VectorXd residual(weights.size());
      for (Eigen::Index i = 0; i < weights.size(); ++i) {
        const double expected = n * weights[i];
        const auto copies = static_cast<std::size_t>(std::floor(expected));
        indices.insert(indices.end(), copies, static_cast<std::size_t>(i));
        residual[i] = expected - static_cast<double>(copies);
      }
      const std::size_t remaining = count - std::min(count, indices.size());
      if (remaining > 0) {
        residual /= residual.sum();
        const std::vector<std::size_t> rest = multinomial(residual, remaining, random);
        // Merge keeps the increasing order the other schemes give.
        std::vector<std::size_t> merged(indices.size() + rest.size());
        std::merge(indices.begin(), indices.end(), rest.begin(), rest.end(), merged.begin());
        indices = std::move(merged);
      }
      indices.resize(count);
      return indices;
    }
  }
  throw std::invalid_argument("resample_indices: unknown resampling scheme");
}

bool should_resample(const ResamplingOptions& options, double effective_sample_fraction) {
  return options.every_frame || effective_sample_fraction < options.ess_threshold;
}

}  // namespace opf
