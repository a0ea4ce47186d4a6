#pragma once
// The particle kernels of the motion step (random_walk_model.h): random walks, shifts, turns.
// Private to lib/particles (not installed): a portion of n particles of dimension D is D
// contiguous rows of n values (x..., y..., z... in double for translation; x..., y..., z..., w...
// in float for rotation quaternions), and each kernel is one pass that vectorises, compiled for
// the CPU at hand (kernel_dispatch.h).

#include <array>
#include <cstddef>

namespace opf::kernels {

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

}  // namespace opf::kernels
