#include "opf/particles/particle_kernels.h"

#include "opf/particles/kernel_dispatch.h"
#include "opf/particles/sorted_gather.h"
#include "opf/particles/vector_math.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace opf::kernels {
namespace {

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
        add(begin, j, l, 2.0f * vmath::atan2_nonnegative_over_y(std::sqrt(t[j]), vw[j]));
      });
  }
  return sums.totals();
}

// The largest value, and whether any is NaN.
OPF_ALWAYS_INLINE double max_value(const double* __restrict a, std::size_t n, bool& has_nan) {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  double top[kLanes] = {kNone, kNone, kNone, kNone, kNone, kNone, kNone, kNone};
  int nan[kLanes] = {};
  std::size_t i = 0;
  for (; i + kLanes <= n; i += kLanes) {
#pragma omp simd
    for (std::size_t l = 0; l < kLanes; ++l) {
      const double v = a[i + l];
      top[l] = v > top[l] ? v : top[l];
      nan[l] |= v != v ? 1 : 0;
    }
  }
  for (; i < n; ++i) {
    top[0] = a[i] > top[0] ? a[i] : top[0];
    nan[0] |= a[i] != a[i] ? 1 : 0;
  }
  int any = 0;
  for (std::size_t l = 0; l < kLanes; ++l) any |= nan[l];
  has_nan = any != 0;
  return lanes_max(top);
}

// marks[ends[i]] = i + 1 in order, so the last particle ending at a slot wins. Kept scalar: an
// AVX-512 scatter (what the vectoriser would emit) is microcoded and slower on AMD.
[[gnu::optimize("no-tree-vectorize")]] void mark_ends(const std::int32_t* ends, std::size_t m,
                                                      std::int32_t* marks) {
  for (std::size_t i = 0; i < m; ++i) marks[ends[i]] = static_cast<std::int32_t>(i + 1);
}

// Resampling by end marks: slot k (of `count`) takes the particle whose interval
// [C_{i-1}, C_i) of cumulative weight / total holds slot k's position. When the positions
// increase with k, particle i's slots end at e_i = #{k : position_k < C_i} (clamped to
// [0, count]), e is nondecreasing, and the particle of slot k is #{i : e_i <= k}. This marks each
// e_i with i + 1 (a later particle overwrites an earlier one); the running maximum of the marks
// over k is then slot k's particle. No branch depends on the weights; the last particle takes any
// remainder left by rounding. Returns count + 1 marks (the last absorbs ends past the last slot).
// Requires n >= 2. `end_of(x)` maps x = count C_i / total to particle i's end slot (before
// clamping).
template <class T, class EndOf>
OPF_ALWAYS_INLINE std::vector<std::int32_t> end_marks(const T* __restrict w, std::size_t n,
                                                      std::size_t count, const EndOf& end_of) {
  if (n >= (std::size_t{1} << 31) || count >= (std::size_t{1} << 31))
    throw std::length_error("resampling by end marks: 2^31 particles or more");
  const std::size_t m = n - 1;  // the last particle's end is `count` by definition
  // Ends in slots: count C_i / total.
  const double total = sum_in_lanes<double, 1>(
      n, [=](std::size_t i, std::size_t l, double(&a)[1][8])
             OPF_INLINE_LAMBDA { a[0][l] += static_cast<double>(w[i]); })[0];
  const double slots = static_cast<double>(count);
  const double per_weight = total > 0.0 ? slots / total : 0.0;
  // The cumulative sums in blocks of eight: each block's own prefix sums in three shift-and-add
  // steps (GCC vector extensions: valignq and vaddpd with AVX-512, the same additions in the same
  // order on any CPU), plus the sum of the blocks before it. Only that last addition carries
  // from block to block. Scratch is left uninitialised: it is written in full before it is read.
  const auto scratch = std::make_unique_for_overwrite<double[]>(m);
  double* __restrict c = scratch.get();
  using Double8 = double __attribute__((vector_size(64)));
  using Index8 = std::int64_t __attribute__((vector_size(64)));
  const Double8 zero = {};
  Double8 carry = {};
  std::size_t i = 0;
  for (; i + 8 <= m; i += 8) {
    Double8 x;
    for (int l = 0; l < 8; ++l) x[l] = static_cast<double>(w[i + l]);
    x += __builtin_shuffle(zero, x, Index8{0, 8, 9, 10, 11, 12, 13, 14});  // + x[l - 1]
    x += __builtin_shuffle(zero, x, Index8{0, 1, 8, 9, 10, 11, 12, 13});   // + x[l - 2]
    x += __builtin_shuffle(zero, x, Index8{0, 1, 2, 3, 8, 9, 10, 11});     // + x[l - 4]
    const Double8 cumulative = x + carry;
    std::memcpy(c + i, &cumulative, sizeof cumulative);
    carry += __builtin_shuffle(x, Index8{7, 7, 7, 7, 7, 7, 7, 7});
  }
  for (double cumulative = carry[0]; i < m; ++i) {
    cumulative += static_cast<double>(w[i]);
    c[i] = cumulative;
  }
  const auto ends = std::make_unique_for_overwrite<std::int32_t[]>(m);
  std::int32_t* __restrict e = ends.get();
#pragma omp simd
  for (std::size_t k = 0; k < m; ++k) {
    const double end = end_of(per_weight * c[k]);
    e[k] = static_cast<std::int32_t>(end < 0.0 ? 0.0 : (end > slots ? slots : end));
  }
  std::vector<std::int32_t> marks(count + 1, 0);
  mark_ends(e, m, marks.data());
  return marks;
}

// Systematic: slot k's position is (k + offset) / count, so particle i's slots end at
// ceil(count C_i / total - offset).
template <class T>
OPF_ALWAYS_INLINE std::vector<std::int32_t> systematic_marks(const T* __restrict w, std::size_t n,
                                                             double offset, std::size_t count) {
  return end_marks(w, n, count, [=](double x) OPF_INLINE_LAMBDA { return std::ceil(x - offset); });
}

// Slot k's particle is the running maximum of the marks up to k.
template <class Index>
OPF_ALWAYS_INLINE void running_maximum(const std::vector<std::int32_t>& marks, std::size_t count,
                                       Index* __restrict indices) {
  std::int32_t particle = 0;
  for (std::size_t k = 0; k < count; ++k) {
    particle = marks[k] > particle ? marks[k] : particle;
    indices[k] = static_cast<Index>(particle);
  }
}

template <class T, class Index>
OPF_ALWAYS_INLINE void systematic(const T* __restrict w, std::size_t n, double offset,
                                  std::size_t count, Index* __restrict indices) {
  if (n < 2 || count == 0) {
    std::fill(indices, indices + count, Index{0});
    return;
  }
  const std::vector<std::int32_t> marks = systematic_marks(w, n, offset, count);
  running_maximum(marks, count, indices);
}

// Systematic resampling straight into the next generation's rows: the running maximum of the
// marks picks each slot's particle and its rows are copied at once (sorted_gather.h), without an
// index array written and read back.
template <class T>
OPF_ALWAYS_INLINE void systematic_gather(const float* __restrict w, std::size_t n, double offset,
                                         const T* __restrict in, std::size_t rows,
                                         T* __restrict out) {
  if (n < 2) {
    std::copy(in, in + rows * n, out);
    return;
  }
  const std::vector<std::int32_t> marks = systematic_marks(w, n, offset, n);
  gather_by_running_maximum(marks.data(), n, in, n, rows, out);
}

}  // namespace

const char* instruction_set() {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(OPF_NO_DISPATCH)
  if (__builtin_cpu_supports("x86-64-v4")) return "x86-64-v4 (AVX-512)";
  if (__builtin_cpu_supports("x86-64-v3")) return "x86-64-v3 (AVX2, FMA)";
  return "x86-64 baseline (SSE2)";
#else
  return "compiler default (no dispatch)";
#endif
}

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

OPF_KERNEL double translation_exponents(const double* __restrict x, std::size_t n,
                                        const std::array<double, 3>& z, double scale,
                                        double* __restrict out, bool accumulate) {
  const double zx = z[0], zy = z[1], zz = z[2];
  return write_exponent_blocks<double>(
      n, out, accumulate,
      [=](std::size_t begin, std::size_t size, double* __restrict block) OPF_INLINE_LAMBDA {
        const double* __restrict px = x + begin;
        const double* __restrict py = x + n + begin;
        const double* __restrict pz = x + 2 * n + begin;
#pragma omp simd
        for (std::size_t j = 0; j < size; ++j) {
          const double dx = px[j] - zx, dy = py[j] - zy, dz = pz[j] - zz;
          block[j] = scale * (dx * dx + dy * dy + dz * dz);
        }
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

OPF_KERNEL NormalisedWeights normalise_log_weights(double* __restrict log_w,
                                                   double* __restrict linear, std::size_t n) {
  if (n == 0) return {};
  bool nan = false;
  const double top = max_value(log_w, n, nan);
  if (nan || !std::isfinite(top)) return {false, 0.0};
  const std::array<double, 2> sums = sum_in_lanes<double, 2>(
      n, [=](std::size_t i, std::size_t l, double(&a)[2][8]) OPF_INLINE_LAMBDA {
        const double w = vmath::exp_nonpositive(log_w[i] - top);
        linear[i] = w;
        a[0][l] += w;
        a[1][l] += w * w;
      });
  const double sum = sums[0], sum_squares = sums[1];
  // Shift by the max first, then by the log-sum of the (small) shifted values: full precision.
  const double shift = top + std::log(sum);
  const double inverse_sum = 1.0 / sum;
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) {
    log_w[i] -= shift;
    linear[i] *= inverse_sum;
  }
  return {true, sum * sum / (static_cast<double>(n) * sum_squares)};
}

OPF_KERNEL NormalisedWeights resampling_weights(const double* __restrict log_w,
                                                float* __restrict linear, std::size_t n) {
  if (n == 0) return {};
  bool nan = false;
  const double top = max_value(log_w, n, nan);
  if (nan || !std::isfinite(top)) return {false, 0.0};
  const std::array<double, 2> sums = sum_in_lanes<float, 2>(
      n, [=](std::size_t i, std::size_t l, float(&a)[2][16]) OPF_INLINE_LAMBDA {
        const float w = vmath::exp_nonpositive(static_cast<float>(log_w[i] - top));
        linear[i] = w;
        a[0][l] += w;
        a[1][l] += w * w;
      });
  return {true, sums[0] * sums[0] / (static_cast<double>(n) * sums[1])};
}

OPF_KERNEL double relative_weights(const double* __restrict log_w, double* __restrict linear,
                                   std::size_t n) {
  bool nan = false;
  const double top = max_value(log_w, n, nan);
  return sum_in_lanes<double, 1>(
      n, [=](std::size_t i, std::size_t l, double(&a)[1][8]) OPF_INLINE_LAMBDA {
        linear[i] = vmath::exp_nonpositive(log_w[i] - top);
        a[0][l] += linear[i];
      })[0];
}

OPF_KERNEL void systematic_indices(const double* w, std::size_t n, double offset, std::size_t count,
                                   std::size_t* indices) {
  systematic(w, n, offset, count, indices);
}

OPF_KERNEL void systematic_indices(const float* w, std::size_t n, double offset, std::size_t count,
                                   std::size_t* indices) {
  systematic(w, n, offset, count, indices);
}

OPF_KERNEL void stratified_indices(const double* w, std::size_t n, const double* uniforms,
                                   std::size_t count, std::size_t* indices) {
  if (n < 2 || count == 0) {
    std::fill(indices, indices + count, std::size_t{0});
    return;
  }
  // Slot k's position is (k + u_k) / count: with m = floor(x), the slots below m all lie under
  // C_i, slot m does when u_m < x - m, and the ones above do not.
  const std::vector<std::int32_t> marks = end_marks(w, n, count, [=](double x) OPF_INLINE_LAMBDA {
    const double m = std::floor(x);
    const auto slot = static_cast<std::size_t>(m < 0.0 ? 0.0 : m);
    return slot >= count ? m : m + (uniforms[slot] < x - m ? 1.0 : 0.0);
  });
  running_maximum(marks, count, indices);
}

OPF_KERNEL void systematic_resample(const float* w, std::size_t n, double offset, const double* in,
                                    std::size_t rows, double* out) {
  if (rows != 3) throw std::invalid_argument("systematic_resample: 3 rows of double expected");
  systematic_gather(w, n, offset, in, rows, out);
}

OPF_KERNEL void systematic_resample(const float* w, std::size_t n, double offset, const float* in,
                                    std::size_t rows, float* out) {
  if (rows != 4) throw std::invalid_argument("systematic_resample: 4 rows of float expected");
  systematic_gather(w, n, offset, in, rows, out);
}

template <class Index>
OPF_ALWAYS_INLINE std::size_t largest(const Index* __restrict indices, std::size_t n) {
  Index top[kLanes] = {};
  std::size_t i = 0;
  for (; i + kLanes <= n; i += kLanes) {
#pragma omp simd
    for (std::size_t l = 0; l < kLanes; ++l)
      top[l] = indices[i + l] > top[l] ? indices[i + l] : top[l];
  }
  for (; i < n; ++i) top[0] = indices[i] > top[0] ? indices[i] : top[0];
  return *std::max_element(top, top + kLanes);
}

OPF_KERNEL std::size_t largest_index(const std::size_t* indices, std::size_t n) {
  return largest(indices, n);
}

template <class T, class Index>
OPF_ALWAYS_INLINE void gather(const T* __restrict in, std::size_t n_in, std::size_t rows,
                              const Index* __restrict indices, std::size_t count,
                              T* __restrict out) {
  for (std::size_t r = 0; r < rows; ++r) {
    const T* row = in + r * n_in;
    T* target = out + r * count;
    for (std::size_t k = 0; k < count; ++k) target[k] = row[indices[k]];
  }
}

OPF_KERNEL void gather_rows(const double* __restrict in, std::size_t n_in, std::size_t rows,
                            const std::size_t* __restrict indices, std::size_t count,
                            double* __restrict out) {
  gather(in, n_in, rows, indices, count, out);
}

OPF_KERNEL void gather_rows(const float* __restrict in, std::size_t n_in, std::size_t rows,
                            const std::size_t* __restrict indices, std::size_t count,
                            float* __restrict out) {
  gather(in, n_in, rows, indices, count, out);
}

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
