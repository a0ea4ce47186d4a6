#pragma once
// The particle kernels of resampling (resampling.h, particle_portion.h): systematic and
// stratified slots, resampling in one pass, gathers.
// Private to lib/particles (not installed): a portion of n particles of dimension D is D
// contiguous rows of n values (x..., y..., z... in double for translation; x..., y..., z..., w...
// in float for rotation quaternions), and each kernel is one pass that vectorises, compiled for
// the CPU at hand (kernel_dispatch.h).

#include <array>
#include <cstddef>

namespace opf::kernels {

/// Systematic resampling of `count` particles from weights w (n of them, any positive total;
/// n and count below 2^31, else std::length_error; the same for stratified_indices):
/// slot k takes the particle whose interval of cumulative weight / total holds
/// (k + offset) / count. Indices ascend. Branch-free passes: each particle's last slot, then a
/// running maximum.
void systematic_indices(const double* w, std::size_t n, double offset, std::size_t count,
                        std::size_t* indices);
void systematic_indices(const float* w, std::size_t n, double offset, std::size_t count,
                        std::size_t* indices);

/// Stratified resampling: as systematic_indices, with slot k at (k + uniforms[k]) / count
/// (`count` uniforms in [0, 1)).
void stratified_indices(const double* w, std::size_t n, const double* uniforms, std::size_t count,
                        std::size_t* indices);

/// Systematic resampling of n particles into n, as systematic_indices, with the particles'
/// rows (`rows` rows of n: 3 of double for translation, 4 of float for rotation) copied from
/// `in` to `out` on the way: no index array is written and read back.
void systematic_resample(const float* w, std::size_t n, double offset, const double* in,
                         std::size_t rows, double* out);
void systematic_resample(const float* w, std::size_t n, double offset, const float* in,
                         std::size_t rows, float* out);

/// The largest of n > 0 indices (the bounds check before a gather).
std::size_t largest_index(const std::size_t* indices, std::size_t n);

/// out row r, slot k = in row r, particle indices[k]; in has n_in columns, out `count`.
void gather_rows(const double* in, std::size_t n_in, std::size_t rows, const std::size_t* indices,
                 std::size_t count, double* out);
void gather_rows(const float* in, std::size_t n_in, std::size_t rows, const std::size_t* indices,
                 std::size_t count, float* out);

}  // namespace opf::kernels
