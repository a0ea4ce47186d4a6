#include "opf/particles/likelihood_kernels.h"

#include "opf/particles/kernel_support.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace opf::kernels {

using namespace detail;

namespace {

// out[i] = e_i, or out[i] += e_i when `accumulate`, for every particle, where
// fill(begin, size, block) writes the exponents of particles [begin, begin + size) to block;
// returns the largest. Without `accumulate`, out is only written (it may hold anything before).
// T is the type the exponents are computed in: float for rotation, whose exponents are then
// added to the double log-weights in a second, cheap loop, so the costly one runs at float width.
template <class T, class FillBlock>
OPF_ALWAYS_INLINE double write_exponent_blocks(std::size_t n, double* __restrict out,
                                               bool accumulate, const FillBlock& fill) {
  constexpr std::size_t kWidth = 64 / sizeof(T);  // lanes of one 512-bit vector
  T best[kWidth];
  std::fill(best, best + kWidth, -std::numeric_limits<T>::infinity());
  alignas(64) T block[kBlock];
  for (std::size_t begin = 0; begin < n; begin += kBlock) {
    const std::size_t size = std::min(kBlock, n - begin);
    fill(begin, size, block);
    double* __restrict o = out + begin;
    std::size_t i = 0;
    for (; i + kWidth <= size; i += kWidth) {
#pragma omp simd
      for (std::size_t l = 0; l < kWidth; ++l) {
        const T e = block[i + l];
        best[l] = e > best[l] ? e : best[l];
        o[i + l] = accumulate ? o[i + l] + static_cast<double>(e) : static_cast<double>(e);
      }
    }
    for (; i < size; ++i) {
      best[0] = block[i] > best[0] ? block[i] : best[0];
      o[i] = accumulate ? o[i] + static_cast<double>(block[i]) : static_cast<double>(block[i]);
    }
  }
  return static_cast<double>(lanes_max(best));
}

}  // namespace

// The exponents of a translation portion: exponent(dx, dy, dz) of each particle's offset from z.
template <class Exponent>
OPF_ALWAYS_INLINE double translation_blocks(const double* __restrict x, std::size_t n,
                                            const std::array<double, 3>& z, double* __restrict out,
                                            bool accumulate, const Exponent& exponent) {
  const double zx = z[0], zy = z[1], zz = z[2];
  return write_exponent_blocks<double>(
      n, out, accumulate,
      [=](std::size_t begin, std::size_t size, double* __restrict block) OPF_INLINE_LAMBDA {
        const double* __restrict px = x + begin;
        const double* __restrict py = x + n + begin;
        const double* __restrict pz = x + 2 * n + begin;
#pragma omp simd
        for (std::size_t j = 0; j < size; ++j)
          block[j] = exponent(px[j] - zx, py[j] - zy, pz[j] - zz);
      });
}

OPF_KERNEL double translation_exponents(const double* __restrict x, std::size_t n,
                                        const std::array<double, 3>& z, double scale,
                                        double* __restrict out, bool accumulate) {
  return translation_blocks(x, n, z, out, accumulate,
                            [=](double dx, double dy, double dz) OPF_INLINE_LAMBDA {
                              return scale * (dx * dx + dy * dy + dz * dz);
                            });
}

OPF_KERNEL double translation_exponents(const double* __restrict x, std::size_t n,
                                        const std::array<double, 3>& z,
                                        const std::array<double, 3>& scale, double* __restrict out,
                                        bool accumulate) {
  const double sx = scale[0], sy = scale[1], sz = scale[2];
  return translation_blocks(x, n, z, out, accumulate,
                            [=](double dx, double dy, double dz) OPF_INLINE_LAMBDA {
                              return sx * (dx * dx) + sy * (dy * dy) + sz * (dz * dz);
                            });
}

OPF_KERNEL double rotation_exponents(const float* __restrict q, std::size_t n,
                                     const std::array<double, 4>& z, double scale,
                                     double* __restrict out, bool accumulate) {
  // z^-1 (z a unit quaternion)
  const auto ix = static_cast<float>(-z[0]), iy = static_cast<float>(-z[1]),
             iz = static_cast<float>(-z[2]), iw = static_cast<float>(z[3]);
  const auto s = static_cast<float>(scale);
  return write_exponent_blocks<float>(
      n, out, accumulate,
      [=](std::size_t begin, std::size_t size, float* __restrict block) OPF_INLINE_LAMBDA {
        const bool concentrated =
            write_and_find_largest(size, block, [=](std::size_t j) OPF_INLINE_LAMBDA {
              const Quat r = multiply({ix, iy, iz, iw}, load(q, n, begin + j));
              return r.x * r.x + r.y * r.y + r.z * r.z;
            }) <= kConcentrated;
        if (concentrated) {
      // theta^2 = (2 |v| asin(|v|) / |v|)^2 = 4 |v|^2 g^2
#pragma omp simd
          for (std::size_t j = 0; j < size; ++j) {
            const float g = vmath::asin_over_x_of_square(block[j]);
            block[j] = 4.0f * s * block[j] * (g * g);
          }
        } else {
#pragma omp simd
          for (std::size_t j = 0; j < size; ++j) {
            const float angle = rotation_angle(multiply({ix, iy, iz, iw}, load(q, n, begin + j)));
            block[j] = s * (angle * angle);
          }
        }
      });
}

OPF_KERNEL void student_t_log_densities(const double* __restrict determinants,
                                        const double* __restrict squared_distances, std::size_t n,
                                        double dof, double dimensions, double log_normaliser,
                                        double* __restrict out) {
  // log(1 + u) rather than log1p(u): its absolute error, an ulp of 1 + u, is far below what a
  // log-density is read to.
  const double tail = 0.5 * (dof + dimensions);
  const double inverse_dof = 1.0 / dof;
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i)
    out[i] = log_normaliser - 0.5 * vmath::log_positive(determinants[i]) -
             tail * vmath::log_positive(1.0 + squared_distances[i] * inverse_dof);
}

}  // namespace opf::kernels
