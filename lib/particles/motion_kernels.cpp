#include "opf/particles/motion_kernels.h"

#include "opf/particles/kernel_support.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace opf::kernels {

using namespace detail;

namespace {

// The tangent random walk q_i <- normalise(q_i exp(e_i)), e_i = s_i (noise rows). exp needs sin
// and cos of half the step's angle: for steps up to 90 degrees (|e|^2 <= pi^2 / 4, every block of
// a random walk that tracks) they come from polynomials in |e|^2 / 4 (no square root, no
// division); longer steps take the reduction and the division.
// With kTurn, each particle is first turned by the world-frame rotation `turn` (the velocity
// drift), in the same pass.
template <bool kPerParticle, bool kTurn = false>
OPF_ALWAYS_INLINE void perturb(float* __restrict q, std::size_t stride, std::size_t count,
                               const float* __restrict noise, float sigma,
                               const double* __restrict sigmas, const Quat& turn = {}) {
  constexpr float kQuarterTurnSquared = static_cast<float>(vmath::kHalfPi * vmath::kHalfPi);
  alignas(64) float t[kBlock];
  for (std::size_t begin = 0; begin < count; begin += kBlock) {
    const std::size_t size = std::min(kBlock, count - begin);
    const float* __restrict nx = noise + begin;
    const float* __restrict ny = noise + count + begin;
    const float* __restrict nz = noise + 2 * count + begin;
    const auto spread = [=](std::size_t j) OPF_INLINE_LAMBDA {
      return kPerParticle ? static_cast<float>(sigmas[begin + j]) : sigma;
    };
    const auto particle = [=](std::size_t j) OPF_INLINE_LAMBDA {
      const Quat p = load(q, stride, begin + j);
      return kTurn ? normalised(multiply(turn, p)) : p;
    };
    const float largest = write_and_find_largest(size, t, [=](std::size_t j) OPF_INLINE_LAMBDA {
      const float s = spread(j);
      return (s * s) * (nx[j] * nx[j] + ny[j] * ny[j] + nz[j] * nz[j]);
    });
    if (largest <= kQuarterTurnSquared) {
#pragma omp simd
      for (std::size_t j = 0; j < size; ++j) {
        float sin_over_x, c;
        vmath::sin_over_x_and_cos_of_square(0.25f * t[j], sin_over_x, c);
        const float f = 0.5f * sin_over_x * spread(j);  // sin(|e|/2) / |e|, times s
        const Quat step{f * nx[j], f * ny[j], f * nz[j], c};
        store(q, stride, begin + j, normalised(multiply(particle(j), step)));
      }
    } else {
#pragma omp simd
      for (std::size_t j = 0; j < size; ++j) {
        const float s = spread(j);
        const Quat step = exp_tangent(s * nx[j], s * ny[j], s * nz[j]);
        store(q, stride, begin + j, normalised(multiply(particle(j), step)));
      }
    }
  }
}

}  // namespace

OPF_KERNEL void add_scaled_noise(double* __restrict x, const float* __restrict noise, double sigma,
                                 std::size_t count) {
#pragma omp simd
  for (std::size_t i = 0; i < count; ++i) x[i] += sigma * static_cast<double>(noise[i]);
}

OPF_KERNEL void add_offset_and_scaled_noise(double* __restrict x, const float* __restrict noise,
                                            double offset, double sigma, std::size_t count) {
#pragma omp simd
  for (std::size_t i = 0; i < count; ++i)
    x[i] = (x[i] + offset) + sigma * static_cast<double>(noise[i]);
}

OPF_KERNEL void add_scaled_noise_per_particle(double* __restrict x, const float* __restrict noise,
                                              const double* __restrict sigma, std::size_t count) {
#pragma omp simd
  for (std::size_t i = 0; i < count; ++i) x[i] += sigma[i] * static_cast<double>(noise[i]);
}

OPF_KERNEL void perturb_quaternions(float* q, std::size_t stride, std::size_t count,
                                    const float* noise, double sigma,
                                    const double* sigma_per_particle) {
  if (sigma_per_particle)
    perturb<true>(q, stride, count, noise, 0.0f, sigma_per_particle);
  else
    perturb<false>(q, stride, count, noise, static_cast<float>(sigma), nullptr);
}

OPF_KERNEL void turn_and_perturb_quaternions(float* q, std::size_t stride, std::size_t count,
                                             const float* noise, double sigma,
                                             const std::array<double, 4>& r) {
  const Quat turn{static_cast<float>(r[0]), static_cast<float>(r[1]), static_cast<float>(r[2]),
                  static_cast<float>(r[3])};
  perturb<false, true>(q, stride, count, noise, static_cast<float>(sigma), nullptr, turn);
}

OPF_KERNEL void rotate_quaternions(float* __restrict q, std::size_t n,
                                   const std::array<double, 4>& r) {
  const auto rx = static_cast<float>(r[0]), ry = static_cast<float>(r[1]),
             rz = static_cast<float>(r[2]), rw = static_cast<float>(r[3]);
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i)
    store(q, n, i, normalised(multiply({rx, ry, rz, rw}, load(q, n, i))));
}

}  // namespace opf::kernels
