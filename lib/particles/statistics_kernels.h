#pragma once
// The particle kernels of the estimate (particle_statistics.h): weighted sums and second moments.
// Private to lib/particles (not installed): a portion of n particles of dimension D is D
// contiguous rows of n values (x..., y..., z... in double for translation; x..., y..., z..., w...
// in float for rotation quaternions), and each kernel is one pass that vectorises, compiled for
// the CPU at hand (kernel_dispatch.h).

#include <array>
#include <cstddef>

namespace opf::kernels {

/// Weighted sums about a reference point (for precision far from the origin): total weight,
/// sum w (x - ref) and the upper triangle of sum w (x - ref)(x - ref)^T (xx, xy, xz, yy, yz, zz).
/// w null means all weights 1.
struct TranslationSums {
  double weight = 0.0;
  std::array<double, 3> first{};
  std::array<double, 6> second{};
};
TranslationSums translation_sums(const double* x, std::size_t n, const double* w,
                                 const std::array<double, 3>& reference);

/// The upper triangle of Markley's M = sum w q q^T over (x, y, z, w) components, row by row:
/// xx xy xz xw yy yz yw zz zw ww. w null means all weights 1.
std::array<double, 10> quaternion_second_moment(const float* q, std::size_t n, const double* w);

/// Upper triangle of sum w d d^T for the tangent vectors d_i = log(mean_inverse * q_i), in the
/// order of TranslationSums::second. w null means all weights 1.
std::array<double, 6> tangent_second_moment(const float* q, std::size_t n, const double* w,
                                            const std::array<double, 4>& mean_inverse);

}  // namespace opf::kernels
