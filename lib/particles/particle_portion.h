#pragma once
// One portion of particles, stored structure-of-arrays: a Dim x N state matrix (one particle per
// column) and its log-weights. The pose filter keeps two: translation (Dim 3) and rotation
// (Dim 4, unit quaternions stored x, y, z, w as Eigen's coeffs()).

#include "particles/log_weights.h"

#include <Eigen/Core>

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace opf {

template <int Dim>
struct ParticlePortion {
  using States = Eigen::Matrix<double, Dim, Eigen::Dynamic>;

  States states;
  LogWeights weights;

  std::size_t size() const { return static_cast<std::size_t>(states.cols()); }

  void resize(std::size_t count) {
    states.resize(Dim, Eigen::Index(count));
    weights = LogWeights(count);
    weights.reset();
  }

  /// Replaces the particles by the ones at `indices` (which may repeat) and makes the weights
  /// uniform: the resampled set represents the posterior by its density alone.
  void resample(const std::vector<std::size_t>& indices) {
    States next(Dim, Eigen::Index(indices.size()));
    for (std::size_t k = 0; k < indices.size(); ++k) {
      if (indices[k] >= size()) throw std::out_of_range("ParticlePortion::resample: bad index");
      next.col(Eigen::Index(k)) = states.col(Eigen::Index(indices[k]));
    }
    states = std::move(next);
    weights = LogWeights(indices.size());
    weights.reset();
  }
};

using TranslationParticles = ParticlePortion<3>;
using RotationParticles = ParticlePortion<4>;

}  // namespace opf
