#pragma once
// One portion of particles, stored structure-of-arrays: a Dim x N row-major state matrix (row d
// holds coordinate d of every particle contiguously, so a pass over one coordinate vectorises)
// and its log-weights. The pose filter keeps two: translation (Dim 3, double) and rotation
// (Dim 4, unit quaternions with rows x, y, z, w as Eigen's coeffs()). Rotation particles are
// single precision: 1e-7 rad of resolution against an observation noise of 0.05 rad, and their
// kernels (a quaternion product, a sine, an arctangent per particle) run at twice the lanes.
// Log-weights are double for both. An estimator may add per-particle columns of its own (the
// occlusion-aware PF's occlusion flag and time occluded): they travel with the states when the
// portion is resampled, so the estimator needs no filter of its own.

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
  /// One row per column, one entry per particle; no rows unless an estimator adds them.
  using Columns = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  States states;
  LogWeights weights;
  Columns columns;

  std::size_t size() const { return static_cast<std::size_t>(states.cols()); }

  /// `count` particles with uniform weights; the columns keep their number and restart at 0.
  void resize(std::size_t count) {
    states.resize(Dim, Eigen::Index(count));
    weights = LogWeights(count);
    columns.setZero(columns.rows(), Eigen::Index(count));
  }

  /// Replaces the particles (states and columns) by the ones at `indices` (which may repeat) and
  /// makes the weights uniform: the resampled set represents the posterior by its density alone.
  void resample(const std::vector<std::size_t>& indices);

  /// Systematic resampling from relative weights (any positive total) with uniform position
  /// `offset` in [0, 1), in one pass over the particles (kernels::systematic_resample). The
  /// states only: std::logic_error for a portion with columns (resample() moves those).
  void resample_systematic(const std::vector<float>& relative, double offset);
};

// Both portions are compiled once, in particle_portion.cpp (beside the kernels they call).
extern template struct ParticlePortion<3>;
extern template struct ParticlePortion<4>;

using TranslationParticles = ParticlePortion<3>;
using RotationParticles = ParticlePortion<4>;

}  // namespace opf
