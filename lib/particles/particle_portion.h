#pragma once
// One portion of particles, stored structure-of-arrays: a Dim x N row-major state matrix (row d
// holds coordinate d of every particle contiguously, so a pass over one coordinate vectorises)
// and its log-weights. The pose filter keeps two: translation (Dim 3, double) and rotation
// (Dim 4, unit quaternions with rows x, y, z, w as Eigen's coeffs()). Rotation particles are
// single precision: 1e-7 rad of resolution against an observation noise of 0.05 rad, and their
// kernels (a quaternion product, a sine, an arctangent per particle) run at twice the lanes.
// Log-weights are double for both.

#include "opf/particles/log_weights.h"
#include "opf/particles/particle_kernels.h"

#include <Eigen/Core>

#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace opf {

template <int Dim, class Scalar = std::conditional_t<Dim == 4, float, double>>
struct ParticlePortion {
  using States = Eigen::Matrix<Scalar, Dim, Eigen::Dynamic, Eigen::RowMajor>;

  States states;
  LogWeights weights;

  std::size_t size() const { return static_cast<std::size_t>(states.cols()); }

  void resize(std::size_t count) {
    states.resize(Dim, Eigen::Index(count));
    weights = LogWeights(count);
  }

  /// Replaces the particles by the ones at `indices` (which may repeat) and makes the weights
  /// uniform: the resampled set represents the posterior by its density alone.
  void resample(const std::vector<std::size_t>& indices) {
    if (!indices.empty() && kernels::largest_index(indices.data(), indices.size()) >= size())
      throw std::out_of_range("ParticlePortion::resample: bad index");
    // A fresh matrix rather than a kept spare: freed and allocated again step after step, the
    // same memory serves every filter on a thread and stays in cache across an ensemble.
    States next(Dim, Eigen::Index(indices.size()));
    kernels::gather_rows(states.data(), size(), Dim, indices.data(), indices.size(), next.data());
    states = std::move(next);
    weights = LogWeights(indices.size());
  }

  /// Systematic resampling from relative weights (any positive total) with uniform position
  /// `offset` in [0, 1), in one pass over the particles (kernels::systematic_resample).
  void resample_systematic(const std::vector<float>& relative, double offset) {
    if (relative.size() != size())
      throw std::invalid_argument("ParticlePortion::resample_systematic: one weight per particle");
    States next(Dim, states.cols());
    kernels::systematic_resample(relative.data(), size(), offset, states.data(), Dim, next.data());
    states = std::move(next);
    weights.reset();
  }
};

using TranslationParticles = ParticlePortion<3>;
using RotationParticles = ParticlePortion<4>;

}  // namespace opf
