#pragma once
// The particle kernels of the measurement update (gaussian_likelihood.h): Gaussian exponents; and
// the Student-t log-densities a motion-model bank weighs its members by (student_t_densities.h).
// Private to lib/particles (not installed): a portion of n particles of dimension D is D
// contiguous rows of n values (x..., y..., z... in double for translation; x..., y..., z..., w...
// in float for rotation quaternions), and each kernel is one pass that vectorises, compiled for
// the CPU at hand (kernel_dispatch.h).

#include <array>
#include <cstddef>

namespace opf::kernels {

/// out[i] (+)= scale * |x_i - z|^2; returns the largest scale * |x_i - z|^2. `accumulate` adds to
/// out (log-weights) instead of overwriting it.
double translation_exponents(const double* x, std::size_t n, const std::array<double, 3>& z,
                             double scale, double* out, bool accumulate);

/// The same with a scale per axis: out[i] (+)= sum_a scale[a] (x_i - z)_a^2 (a diagonal Q).
double translation_exponents(const double* x, std::size_t n, const std::array<double, 3>& z,
                             const std::array<double, 3>& scale, double* out, bool accumulate);

/// out[i] (+)= scale * theta_i^2 with theta_i the geodesic angle between q_i and z; returns the
/// largest such exponent.
double rotation_exponents(const float* q, std::size_t n, const std::array<double, 4>& z,
                          double scale, double* out, bool accumulate);

/// out[i] = log_normaliser - 0.5 log determinants[i] - 0.5 (dof + dimensions)
/// log(1 + squared_distances[i] / dof). Determinants positive and normal.
void student_t_log_densities(const double* determinants, const double* squared_distances,
                             std::size_t n, double dof, double dimensions, double log_normaliser,
                             double* out);

}  // namespace opf::kernels
