#include "opf/particles/statistics_kernels.h"

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

template <bool kWeighted>
OPF_ALWAYS_INLINE TranslationSums sums(const double* __restrict x, std::size_t n,
                                       const double* __restrict w,
                                       const std::array<double, 3> reference) {
  const double rx = reference[0], ry = reference[1], rz = reference[2];
  const std::array<double, 10> s = sum_in_lanes<double, 10>(
      n, [=](std::size_t i, std::size_t l, double(&a)[10][8]) OPF_INLINE_LAMBDA {
        const double wi = kWeighted ? w[i] : 1.0;
        const double dx = x[i] - rx, dy = x[n + i] - ry, dz = x[2 * n + i] - rz;
        a[0][l] += wi;
        a[1][l] += wi * dx;
        a[2][l] += wi * dy;
        a[3][l] += wi * dz;
        add_outer_product<4>(a, l, wi, dx, dy, dz);
      });
  return {s[0], {s[1], s[2], s[3]}, {s[4], s[5], s[6], s[7], s[8], s[9]}};
}

template <bool kWeighted>
OPF_ALWAYS_INLINE std::array<double, 10> markley(const float* __restrict q, std::size_t n,
                                                 const double* __restrict w) {
  return sum_in_lanes<double, 10>(
      n, [=](std::size_t i, std::size_t l, double(&a)[10][8]) OPF_INLINE_LAMBDA {
        const double wi = kWeighted ? w[i] : 1.0;
        const double vx = q[i], vy = q[n + i], vz = q[2 * n + i], vw = q[3 * n + i];
        const double wx = wi * vx, wy = wi * vy, wz = wi * vz;
        a[0][l] += wx * vx;
        a[1][l] += wx * vy;
        a[2][l] += wx * vz;
        a[3][l] += wx * vw;
        a[4][l] += wy * vy;
        a[5][l] += wy * vz;
        a[6][l] += wy * vw;
        a[7][l] += wz * vz;
        a[8][l] += wz * vw;
        a[9][l] += wi * vw * vw;
      });
}

// Sums of the tangent outer products in single precision (sixteen lanes, each adding n/16
// terms: rounding near 1e-6 relative for the counts we use). Particle i adds to lane i mod 16,
// as in sum_in_lanes: blocks are a whole number of lanes.
template <bool kWeighted>
OPF_ALWAYS_INLINE std::array<double, 6> tangent(const float* __restrict q, std::size_t n,
                                                const double* __restrict w, const Quat inverse) {
  // The invariants are copied to plain locals: GCC 12 does not vectorise this loop for AVX-512
  // when they are read through a reference.
  const float ix = inverse.x, iy = inverse.y, iz = inverse.z, iw = inverse.w;
  LaneSums<float, 6> sums;
  float(&a)[6][16] = sums.lanes;
  // r_i = mean^-1 q_i on the hemisphere w >= 0, and |v|^2
  alignas(64) float vx[kBlock], vy[kBlock], vz[kBlock], vw[kBlock], t[kBlock];
  const auto add = [&](std::size_t begin, std::size_t j, std::size_t l, float factor)
                       OPF_INLINE_LAMBDA {
                         const float wi = kWeighted ? static_cast<float>(w[begin + j]) : 1.0f;
                         const float dx = factor * vx[j], dy = factor * vy[j], dz = factor * vz[j];
                         add_outer_product<0>(a, l, wi, dx, dy, dz);
                       };
  for (std::size_t begin = 0; begin < n; begin += kBlock) {
    const std::size_t size = std::min(kBlock, n - begin);
    const bool concentrated = write_and_find_largest(size, t, [&](std::size_t j) OPF_INLINE_LAMBDA {
                                const Quat r = multiply({ix, iy, iz, iw}, load(q, n, begin + j));
                                const float sign = r.w < 0.0f ? -1.0f : 1.0f;
                                vx[j] = sign * r.x;
                                vy[j] = sign * r.y;
                                vz[j] = sign * r.z;
                                vw[j] = sign * r.w;
                                return r.x * r.x + r.y * r.y + r.z * r.z;
                              }) <= kConcentrated;
    // log: d = 2 atan2(|v|, w) v / |v| = 2 (asin(|v|) / |v|) v, -> 2 v as |v| -> 0.
    if (concentrated)
      in_lanes<16>(size, [&](std::size_t j, std::size_t l) OPF_INLINE_LAMBDA {
        add(begin, j, l, 2.0f * vmath::asin_over_x_of_square(t[j]));
      });
    else
      in_lanes<16>(size, [&](std::size_t j, std::size_t l) OPF_INLINE_LAMBDA {
        add(begin, j, l, 2.0f * vmath::atan2_unit_over_y_of_square(t[j], vw[j]));
      });
  }
  return sums.totals();
}

}  // namespace

OPF_KERNEL TranslationSums translation_sums(const double* x, std::size_t n, const double* w,
                                            const std::array<double, 3>& reference) {
  return w ? sums<true>(x, n, w, reference) : sums<false>(x, n, nullptr, reference);
}

OPF_KERNEL std::array<double, 10> quaternion_second_moment(const float* q, std::size_t n,
                                                           const double* w) {
  return w ? markley<true>(q, n, w) : markley<false>(q, n, nullptr);
}

OPF_KERNEL std::array<double, 6> tangent_second_moment(const float* q, std::size_t n,
                                                       const double* w,
                                                       const std::array<double, 4>& mean_inverse) {
  const Quat inverse{static_cast<float>(mean_inverse[0]), static_cast<float>(mean_inverse[1]),
                     static_cast<float>(mean_inverse[2]), static_cast<float>(mean_inverse[3])};
  return w ? tangent<true>(q, n, w, inverse) : tangent<false>(q, n, nullptr, inverse);
}

}  // namespace opf::kernels
