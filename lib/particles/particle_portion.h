#pragma once
// One portion of particles, stored structure-of-arrays: a Dim x N row-major state matrix (row d
// holds coordinate d of every particle contiguously, so a pass over one coordinate vectorises)
// and its log-weights. The pose filter keeps two: translation (Dim 3, double) and rotation
// (Dim 4, unit quaternions with rows x, y, z, w as Eigen's coeffs()). Rotation particles are
// single precision: 1e-7 rad of resolution against an observation noise of 0.05 rad, and their
// kernels (a quaternion product, a sine, an arctangent per particle) run at twice the lanes.
// Log-weights are double for both.

#include "opf/particles/log_weights.h"

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
  void resample(const std::vector<std::size_t>& indices);

  /// Systematic resampling from relative weights (any positive total) with uniform position
  /// `offset` in [0, 1), in one pass over the particles (kernels::systematic_resample).
  void resample_systematic(const std::vector<float>& relative, double offset);
};

// Both portions are compiled once, in particle_portion.cpp (beside the kernels they call).
extern template struct ParticlePortion<3>;
extern template struct ParticlePortion<4>;

using TranslationParticles = ParticlePortion<3>;
using RotationParticles = ParticlePortion<4>;

}  // namespace opf
