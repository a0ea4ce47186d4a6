#pragma once
// What the particle kernels share (private to lib/particles, not installed): the single-precision
// quaternion and its operations, sums in fixed lanes, lane maxima, and the blocks the rotation
// kernels run over. Everything is inlined into each kernel's versions (kernel_dispatch.h).

#include "opf/particles/kernel_dispatch.h"
#include "opf/particles/vector_math.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace opf::kernels::detail {

// Rotation particles are unit quaternions in single precision (x, y, z, w rows): 1e-7 rad of
// resolution against an observation noise of 0.05 rad, at twice the lanes of double.
struct Quat {
  float x, y, z, w;
  // Keeps the struct off 16 bytes: GCC 12 copies a 16-byte struct of floats as one 128-bit
  // block, which stops the vectoriser ("no vectype") in every loop that builds one.
  float unused = 0.0f;
};

// Hamilton product a * b.
OPF_ALWAYS_INLINE Quat multiply(const Quat& a, const Quat& b) {
  return {
      a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
      a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

OPF_ALWAYS_INLINE Quat normalised(const Quat& q) {
  const float inverse = 1.0f / std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  return {q.x * inverse, q.y * inverse, q.z * inverse, q.w * inverse};
}

OPF_ALWAYS_INLINE Quat load(const float* q, std::size_t n, std::size_t i) {
  return {q[i], q[n + i], q[2 * n + i], q[3 * n + i]};
}

OPF_ALWAYS_INLINE void store(float* q, std::size_t n, std::size_t i, const Quat& v) {
  q[i] = v.x;
  q[n + i] = v.y;
  q[2 * n + i] = v.z;
  q[3 * n + i] = v.w;
}

// exp of the tangent step v: (sin(|v|/2) v/|v|, cos(|v|/2)), with the limit 1/2 of
// sin(|v|/2)/|v| at 0.
OPF_ALWAYS_INLINE Quat exp_tangent(float vx, float vy, float vz) {
  const float angle = std::sqrt(vx * vx + vy * vy + vz * vz);
  float s, c;
  vmath::sincos(0.5f * angle, s, c);
  const float factor = angle > 1e-30f ? s / angle : 0.5f;
  return {factor * vx, factor * vy, factor * vz, c};
}

// The geodesic angle of the rotation r (any sign): 2 atan2(|v|, |w|), in [0, pi].
OPF_ALWAYS_INLINE float rotation_angle(const Quat& r) {
  const float v = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
  return 2.0f * v * vmath::atan2_nonnegative_over_y(v, std::fabs(r.w));
}

// Sums over particles run in fixed lanes: particle i adds to lane i mod W (W = one 512-bit
// vector), and the lanes are added up in a fixed order at the end. Unlike `omp simd reduction`,
// whose partial sums follow the vector width and the array's alignment, the result is then the
// same whatever the CPU, the heap address or the thread. `terms(i, l, lanes)` adds particle i's
// terms to lanes[k][l].
template <class T, int K>
struct LaneSums {
  static constexpr std::size_t kWidth = 64 / sizeof(T);
  alignas(64) T lanes[K][kWidth] = {};

  std::array<double, K> totals() const {
    std::array<double, K> total{};
    for (int k = 0; k < K; ++k)
      for (std::size_t l = 0; l < kWidth; ++l) total[k] += static_cast<double>(lanes[k][l]);
    return total;
  }
};

template <class T, int K, class Terms>
OPF_ALWAYS_INLINE std::array<double, K> sum_in_lanes(std::size_t n, const Terms& terms) {
  LaneSums<T, K> sums;
  constexpr std::size_t kWidth = LaneSums<T, K>::kWidth;
  std::size_t i = 0;
  for (; i + kWidth <= n; i += kWidth) {
#pragma omp simd
    for (std::size_t l = 0; l < kWidth; ++l) terms(i + l, l, sums.lanes);
  }
  for (std::size_t l = 0; i < n; ++i, ++l) terms(i, l, sums.lanes);
  return sums.totals();
}

// a[First..First+5][l] += w times the upper triangle of d d^T (xx, xy, xz, yy, yz, zz).
template <int First, class T, int K, std::size_t W>
OPF_ALWAYS_INLINE void add_outer_product(T (&a)[K][W], std::size_t l, T w, T dx, T dy, T dz) {
  a[First][l] += w * dx * dx;
  a[First + 1][l] += w * dx * dy;
  a[First + 2][l] += w * dx * dz;
  a[First + 3][l] += w * dy * dy;
  a[First + 4][l] += w * dy * dz;
  a[First + 5][l] += w * dz * dz;
}

// Maximum reductions run in eight explicit lanes: GCC 12 leaves `omp simd reduction(max)` over
// doubles scalar (it must keep std::max's NaN semantics), while `a > b ? a : b` per lane is one
// vmaxpd. NaN terms never win a lane.
constexpr std::size_t kLanes = 8;

template <class T, std::size_t W>
OPF_ALWAYS_INLINE T lanes_max(const T (&lanes)[W]) {
  T top = lanes[0];
  for (std::size_t l = 1; l < W; ++l) top = lanes[l] > top ? lanes[l] : top;
  return top;
}

// Rotation kernels run over blocks of particles held in L1: a first pass finds |v|^2 (the
// squared sine of half the angle) and its largest value in the block; when every particle in
// the block is within 60 degrees (|v|^2 <= 1/4, as in any cloud that tracks), the angle comes
// from asin's polynomial in |v|^2 with no square root or division (which bound these loops'
// throughput); otherwise from atan2. The choice is per block, so a stray particle costs its
// block the slow path only.
constexpr std::size_t kBlock = 256;
constexpr float kConcentrated = 0.25f;  // |v|^2 <= 1/4: asin_over_x_of_square's domain
// Runs body(j, l) for j < size in vectorised chunks of W lanes (l = j mod W), then the tail.
template <std::size_t W, class Body>
OPF_ALWAYS_INLINE void in_lanes(std::size_t size, const Body& body) {
  std::size_t j = 0;
  for (; j + W <= size; j += W) {
#pragma omp simd
    for (std::size_t l = 0; l < W; ++l) body(j + l, l);
  }
  for (std::size_t l = 0; j < size; ++j, ++l) body(j, l);
}

// t[j] = value(j) for j < size, and the largest of them (NaN never is: both paths chosen on it
// carry NaN through).
template <class Value>
OPF_ALWAYS_INLINE float write_and_find_largest(std::size_t size, float* __restrict t,
                                               const Value& value) {
  float top[16] = {};
  in_lanes<16>(size, [&](std::size_t j, std::size_t l) OPF_INLINE_LAMBDA {
    t[j] = value(j);
    top[l] = t[j] > top[l] ? t[j] : top[l];
  });
  return lanes_max(top);
}

}  // namespace opf::kernels::detail
