#pragma once
// The per-particle loops of a filter step over structure-of-arrays storage: a portion of n
// particles of dimension D is D contiguous rows of n values: x..., y..., z... in double for
// translation; x..., y..., z..., w... in float for rotation quaternions. Each kernel is one pass
// that vectorises, compiled for the CPU at hand (kernel_dispatch.h). The filters call these through
// their typed steps (random_walk_model.h, gaussian_likelihood.h, log_weights.h, resampling.h,
// particle_statistics.h); nothing else needs them.

#include <array>
#include <cstddef>

namespace opf::kernels {

/// Which version of the kernels this CPU runs: "x86-64-v4 (AVX-512)", "x86-64-v3 (AVX2, FMA)" or
/// "x86-64 baseline (SSE2)" (kernel_dispatch.h); for benchmark reports.
const char* instruction_set();

/// x[i] += sigma * noise[i] for i < count.
void add_scaled_noise(double* x, const float* noise, double sigma, std::size_t count);

/// x[i] = (x[i] + offset) + sigma * noise[i] for i < count: a rigid shift and the random walk in
/// one pass over the particles.
void add_offset_and_scaled_noise(double* x, const float* noise, double offset, double sigma,
                                 std::size_t count);

/// x[i] += sigma[i] * noise[i] for i < count: a spread per particle.
void add_scaled_noise_per_particle(double* x, const float* noise, const double* sigma,
                                   std::size_t count);

/// q_i <- normalise(q_i * exp(e_i)) for i < count, where q's rows are `stride` apart and the
/// tangent step is e_i = s_i (noise[i], noise[count + i], noise[2 count + i]) with
/// s_i = sigma_per_particle[i], or `sigma` when that is null.
void perturb_quaternions(float* q, std::size_t stride, std::size_t count, const float* noise,
                         double sigma, const double* sigma_per_particle);

/// q_i <- normalise(normalise(r * q_i) * exp(e_i)) with e_i as above (one spread `sigma`): a
/// world-frame turn r (x, y, z, w) and the random walk in one pass, with rotate_quaternions'
/// and perturb_quaternions' arithmetic.
void turn_and_perturb_quaternions(float* q, std::size_t stride, std::size_t count,
                                  const float* noise, double sigma, const std::array<double, 4>& r);

/// q_i <- normalise(r * q_i): every particle turned by the world-frame rotation r (x, y, z, w).
void rotate_quaternions(float* q, std::size_t n, const std::array<double, 4>& r);

/// out[i] (+)= scale * |x_i - z|^2; returns the largest scale * |x_i - z|^2. `accumulate` adds to
/// out (log-weights) instead of overwriting it.
double translation_exponents(const double* x, std::size_t n, const std::array<double, 3>& z,
                             double scale, double* out, bool accumulate);

/// out[i] (+)= scale * theta_i^2 with theta_i the geodesic angle between q_i and z; returns the
/// largest such exponent.
double rotation_exponents(const float* q, std::size_t n, const std::array<double, 4>& z,
                          double scale, double* out, bool accumulate);

/// What one normalisation of log-weights found.
struct NormalisedWeights {
  bool usable = true;         ///< false when every weight was -inf or any was NaN
  double ess_fraction = 1.0;  ///< (sum w)^2 / (n sum w^2) of the weights on entry
};

/// Shifts log_w so that exp(log_w) sums to one and writes those linear weights to `linear`, in
/// one pass of exponentials. When no weight is usable, returns usable = false and leaves both
/// arrays untouched.
NormalisedWeights normalise_log_weights(double* log_w, double* linear, std::size_t n);

/// Relative weights for resampling right away: linear[i] = exp(log_w[i] - max log_w) in single
/// precision (a weight below e^-87 of the largest is 0), and the ESS fraction. log_w is left as
/// it is (resampling makes it uniform). usable = false when every weight was -inf or any NaN.
NormalisedWeights resampling_weights(const double* log_w, float* linear, std::size_t n);

/// linear[i] = exp(log_w[i] - max log_w) (unnormalised, largest 1); returns their sum.
double relative_weights(const double* log_w, double* linear, std::size_t n);

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
