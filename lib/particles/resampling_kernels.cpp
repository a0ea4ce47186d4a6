#include "opf/particles/resampling_kernels.h"

#include "opf/particles/kernel_support.h"
#include "opf/particles/sorted_gather.h"

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
  // steps (the same additions in the same order on any CPU), plus the sum of the blocks before
  // it. Only that last addition carries from block to block. The block is two halves of four
  // (GCC vector extensions), which AVX2 holds in registers as AVX-512 does: an eight-wide vector
  // on AVX2 went through the stack at every step. Scratch is left uninitialised: it is written in
  // full before it is read.
  const auto scratch = std::make_unique_for_overwrite<double[]>(m);
  double* __restrict c = scratch.get();
  using Double4 = double __attribute__((vector_size(32)));
  using Index4 = std::int64_t __attribute__((vector_size(32)));
  const Double4 zero = {};
  Double4 carry = {};
  std::size_t i = 0;
  for (; i + 8 <= m; i += 8) {
    Double4 lo, hi;
    for (int l = 0; l < 4; ++l) {
      lo[l] = static_cast<double>(w[i + l]);
      hi[l] = static_cast<double>(w[i + 4 + l]);
    }
    Double4 lo_shifted = __builtin_shuffle(zero, lo, Index4{0, 4, 5, 6});  // + x[l - 1]
    Double4 hi_shifted = __builtin_shuffle(lo, hi, Index4{3, 4, 5, 6});
    lo += lo_shifted;
    hi += hi_shifted;
    lo_shifted = __builtin_shuffle(zero, lo, Index4{0, 1, 4, 5});  // + x[l - 2]
    hi_shifted = __builtin_shuffle(lo, hi, Index4{2, 3, 4, 5});
    lo += lo_shifted;
    hi += hi_shifted;
    hi += lo;  // + x[l - 4]
    const Double4 cumulative_lo = lo + carry;
    const Double4 cumulative_hi = hi + carry;
    std::memcpy(c + i, &cumulative_lo, sizeof cumulative_lo);
    std::memcpy(c + i + 4, &cumulative_hi, sizeof cumulative_hi);
    carry += __builtin_shuffle(hi, Index4{3, 3, 3, 3});
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

}  // namespace opf::kernels
