#include "opf/particles/sorted_gather.h"

#include "opf/particles/kernel_dispatch.h"

#include <algorithm>
#include <utility>

#ifdef OPF_KERNEL_DISPATCH
#include <immintrin.h>
// GCC 12's intrinsics pass _mm512_undefined_epi32() as the unused merge source, which trips
// -Wmaybe-uninitialized where they are inlined (GCC bug 105593, fixed in GCC 13).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace opf::kernels {
namespace {

template <int Rows, class T>
void scalar_rows(const std::int32_t* __restrict marks, std::size_t begin, std::size_t count,
                 std::int32_t particle, const T* __restrict in, std::size_t n, std::size_t rows,
                 T* __restrict out) {
  const std::size_t row_count = Rows > 0 ? static_cast<std::size_t>(Rows) : rows;
  for (std::size_t k = begin; k < count; ++k) {
    particle = marks[k] > particle ? marks[k] : particle;
    const auto p = static_cast<std::size_t>(particle);
    for (std::size_t r = 0; r < row_count; ++r) out[r * count + k] = in[r * n + p];
  }
}

// Slots [begin, count) from the running maximum `particle` so far.
template <class T>
void scalar_tail(const std::int32_t* marks, std::size_t begin, std::size_t count,
                 std::int32_t particle, const T* in, std::size_t n, std::size_t rows, T* out) {
  if (rows == 3) return scalar_rows<3>(marks, begin, count, particle, in, n, rows, out);
  if (rows == 4) return scalar_rows<4>(marks, begin, count, particle, in, n, rows, out);
  scalar_rows<0>(marks, begin, count, particle, in, n, rows, out);
}

#ifdef OPF_KERNEL_DISPATCH

// The running maximum within a block of sixteen marks: four shift-and-max steps. It does not
// depend on earlier blocks, so blocks overlap in the pipeline; the previous blocks' maximum is
// applied afterwards with one max (the only dependence from block to block).
[[gnu::target("avx512f")]] inline __m512i block_running_maximum(const std::int32_t* marks) {
  const __m512i zero = _mm512_setzero_si512();
  __m512i m = _mm512_loadu_si512(marks);
  m = _mm512_max_epi32(m, _mm512_alignr_epi32(m, zero, 15));  // lane l sees lane l - 1
  m = _mm512_max_epi32(m, _mm512_alignr_epi32(m, zero, 14));
  m = _mm512_max_epi32(m, _mm512_alignr_epi32(m, zero, 12));
  return _mm512_max_epi32(m, _mm512_alignr_epi32(m, zero, 8));
}

// The lanes of a window [base, base + 2 width) that lie inside a row of n values; masked-off
// lanes are not read.
inline std::uint32_t lanes_inside(std::size_t available, std::size_t width) {
  return available >= width ? (1u << width) - 1u : (1u << available) - 1u;
}

template <class T>
void scalar_block(const std::int32_t* p, std::size_t k, const T* in, std::size_t n,
                  std::size_t rows, std::size_t count, std::size_t lanes, T* out) {
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t l = 0; l < lanes; ++l)
      out[r * count + k + l] = in[r * n + static_cast<std::size_t>(p[l])];
}

#endif

}  // namespace

bool gather_uses_permutes() {
  return cpu_has_avx512f();
}

bool gather_uses_avx2() {
#ifdef OPF_KERNEL_DISPATCH
  static const bool available = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return available && !gather_uses_permutes();
#else
  return false;
#endif
}

void gather_by_running_maximum_scalar(const std::int32_t* marks, std::size_t count, const float* in,
                                      std::size_t n, std::size_t rows, float* out) {
  scalar_tail(marks, 0, count, 0, in, n, rows, out);
}

void gather_by_running_maximum_scalar(const std::int32_t* marks, std::size_t count,
                                      const double* in, std::size_t n, std::size_t rows,
                                      double* out) {
  scalar_tail(marks, 0, count, 0, in, n, rows, out);
}

#ifdef OPF_KERNEL_DISPATCH

namespace {

// The slots in blocks of sixteen: each block's particles (the running maximum, carried over from
// the blocks before) go to copy(p, k, particles) with p their array and k the block's first slot;
// the slots after the last whole block are copied by the scalar path.
template <class T, class CopyBlock>
[[gnu::target("avx512f")]] void for_each_block(const std::int32_t* marks, std::size_t count,
                                               const T* in, std::size_t n, std::size_t rows, T* out,
                                               const CopyBlock& copy) {
  const __m512i last_lane = _mm512_set1_epi32(15);
  __m512i carry = _mm512_setzero_si512();
  alignas(64) std::int32_t p[16];
  std::size_t k = 0;
  for (; k + 16 <= count; k += 16) {
    const __m512i local = block_running_maximum(marks + k);
    const __m512i particles = _mm512_max_epi32(local, carry);
    carry = _mm512_max_epi32(carry, _mm512_permutexvar_epi32(last_lane, local));
    _mm512_store_si512(p, particles);
    copy(p, k, particles);
  }
  scalar_tail(marks, k, count, k > 0 ? p[15] : 0, in, n, rows, out);
}

// The masks of a window of two vectors of `width` lanes starting `available` values before the
// end of its row: lanes past the end are not read.
inline std::pair<std::uint32_t, std::uint32_t> window_masks(std::size_t available,
                                                            std::size_t width) {
  return {lanes_inside(available, width),
          available > width ? lanes_inside(available - width, width) : 0u};
}

// Float rows: when a block's particles span fewer than 32, each row's block is the permute of a
// 32-value window starting at the block's first particle. Rows > 0 fixes the row count at compile
// time. The sizes are copied into locals: the vector stores may alias anything, and would
// otherwise make the compiler reload them from the functor after every store.
template <int Rows>
struct FloatBlocks {
  const float* in;
  std::size_t n, rows, count;
  float* out;

  [[gnu::target("avx512f")]] void operator()(const std::int32_t* p, std::size_t k,
                                             __m512i particles) const {
    const float* const source = in;
    float* const target = out;
    const std::size_t size = n, slots = count;
    const std::size_t row_count = Rows > 0 ? static_cast<std::size_t>(Rows) : rows;
    const std::int32_t base = p[0];
    if (p[15] - base >= 32) return scalar_block(p, k, source, size, row_count, slots, 16, target);
    const __m512i offsets = _mm512_sub_epi32(particles, _mm512_set1_epi32(base));
    const auto [low, high] = window_masks(size - static_cast<std::size_t>(base), 16);
    for (std::size_t r = 0; r < row_count; ++r) {
      const float* window = source + r * size + static_cast<std::size_t>(base);
      const __m512 a = _mm512_maskz_loadu_ps(static_cast<__mmask16>(low), window);
      const __m512 b = high ? _mm512_maskz_loadu_ps(static_cast<__mmask16>(high), window + 16)
                            : _mm512_setzero_ps();
      _mm512_storeu_ps(target + r * slots + k, _mm512_permutex2var_ps(a, offsets, b));
    }
  }
};

// Double rows: the same in two halves of eight slots, each from a window of 16 values.
template <int Rows>
struct DoubleBlocks {
  const double* in;
  std::size_t n, rows, count;
  double* out;

  [[gnu::target("avx512f")]] void operator()(const std::int32_t* p, std::size_t k,
                                             __m512i particles) const {
    const double* const source = in;
    double* const target = out;
    const std::size_t size = n, slots = count;
    const std::size_t row_count = Rows > 0 ? static_cast<std::size_t>(Rows) : rows;
    for (std::size_t half = 0; half < 2; ++half) {
      const std::int32_t* q = p + 8 * half;
      const std::size_t slot = k + 8 * half;
      const std::int32_t base = q[0];
      if (q[7] - base >= 16) {
        scalar_block(q, slot, source, size, row_count, slots, 8, target);
        continue;
      }
      const __m256i eight =
          half == 0 ? _mm512_castsi512_si256(particles) : _mm512_extracti64x4_epi64(particles, 1);
      const __m512i offsets =
          _mm512_sub_epi64(_mm512_cvtepi32_epi64(eight), _mm512_set1_epi64(base));
      const auto [low, high] = window_masks(size - static_cast<std::size_t>(base), 8);
      for (std::size_t r = 0; r < row_count; ++r) {
        const double* window = source + r * size + static_cast<std::size_t>(base);
        const __m512d a = _mm512_maskz_loadu_pd(static_cast<__mmask8>(low), window);
        const __m512d b = high ? _mm512_maskz_loadu_pd(static_cast<__mmask8>(high), window + 8)
                               : _mm512_setzero_pd();
        _mm512_storeu_pd(target + r * slots + slot, _mm512_permutex2var_pd(a, offsets, b));
      }
    }
  }
};

}  // namespace

void gather_by_running_maximum_permute(const std::int32_t* marks, std::size_t count,
                                       const float* in, std::size_t n, std::size_t rows,
                                       float* out) {
  if (rows == 4)
    for_each_block(marks, count, in, n, rows, out, FloatBlocks<4>{in, n, rows, count, out});
  else
    for_each_block(marks, count, in, n, rows, out, FloatBlocks<0>{in, n, rows, count, out});
}

void gather_by_running_maximum_permute(const std::int32_t* marks, std::size_t count,
                                       const double* in, std::size_t n, std::size_t rows,
                                       double* out) {
  if (rows == 3)
    for_each_block(marks, count, in, n, rows, out, DoubleBlocks<3>{in, n, rows, count, out});
  else
    for_each_block(marks, count, in, n, rows, out, DoubleBlocks<0>{in, n, rows, count, out});
}

// Float rows with AVX2, for CPUs without AVX-512: blocks of eight slots from a window of sixteen
// consecutive particles, each row's block two masked loads, two one-source permutes and a blend.
namespace {

// The running maximum within a block of eight marks: three shift-and-max steps. A lane with
// nothing s lanes before it takes its own value again, which leaves its maximum unchanged.
[[gnu::target("avx2")]] inline __m256i block_running_maximum_avx2(const std::int32_t* marks) {
  __m256i m = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(marks));
  m = _mm256_max_epi32(m,
                       _mm256_permutevar8x32_epi32(m, _mm256_setr_epi32(0, 0, 1, 2, 3, 4, 5, 6)));
  m = _mm256_max_epi32(m,
                       _mm256_permutevar8x32_epi32(m, _mm256_setr_epi32(0, 1, 0, 1, 2, 3, 4, 5)));
  return _mm256_max_epi32(
      m, _mm256_permutevar8x32_epi32(m, _mm256_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3)));
}

template <class CopyBlock>
[[gnu::target("avx2")]] void for_each_block_avx2(const std::int32_t* marks, std::size_t count,
                                                 const float* in, std::size_t n, std::size_t rows,
                                                 float* out, const CopyBlock& copy) {
  const __m256i last_lane = _mm256_set1_epi32(7);
  __m256i carry = _mm256_setzero_si256();
  alignas(32) std::int32_t p[8];
  std::size_t k = 0;
  for (; k + 8 <= count; k += 8) {
    const __m256i local = block_running_maximum_avx2(marks + k);
    const __m256i particles = _mm256_max_epi32(local, carry);
    carry = _mm256_max_epi32(carry, _mm256_permutevar8x32_epi32(local, last_lane));
    _mm256_store_si256(reinterpret_cast<__m256i*>(p), particles);
    copy(p, k, particles);
  }
  scalar_tail(marks, k, count, k > 0 ? p[7] : 0, in, n, rows, out);
}

// Lane i of a window is read when i + first < available (the values left in the row; capped,
// since only the first sixteen matter).
[[gnu::target("avx2")]] inline __m256i lanes_below(std::size_t available, int first) {
  const auto left = static_cast<std::int32_t>(std::min<std::size_t>(available, 64));
  return _mm256_cmpgt_epi32(_mm256_set1_epi32(left - first),
                            _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
}

template <int Rows>
struct FloatBlocksAvx2 {
  const float* in;
  std::size_t n, rows, count;
  float* out;

  [[gnu::target("avx2")]] void operator()(const std::int32_t* p, std::size_t k,
                                          __m256i particles) const {
    const float* const source = in;
    float* const target = out;
    const std::size_t size = n, slots = count;
    const std::size_t row_count = Rows > 0 ? static_cast<std::size_t>(Rows) : rows;
    const std::int32_t base = p[0];
    if (p[7] - base >= 16) return scalar_block(p, k, source, size, row_count, slots, 8, target);
    const __m256i offsets = _mm256_sub_epi32(particles, _mm256_set1_epi32(base));
    const __m256 from_second =
        _mm256_castsi256_ps(_mm256_cmpgt_epi32(offsets, _mm256_set1_epi32(7)));
    const std::size_t available = size - static_cast<std::size_t>(base);
    const __m256i low = lanes_below(available, 0), high = lanes_below(available, 8);
    for (std::size_t r = 0; r < row_count; ++r) {
      const float* window = source + r * size + static_cast<std::size_t>(base);
      const __m256 a = _mm256_maskload_ps(window, low);
      const __m256 b = available > 8 ? _mm256_maskload_ps(window + 8, high) : _mm256_setzero_ps();
      _mm256_storeu_ps(target + r * slots + k,
                       _mm256_blendv_ps(_mm256_permutevar8x32_ps(a, offsets),
                                        _mm256_permutevar8x32_ps(b, offsets), from_second));
    }
  }
};

}  // namespace

void gather_by_running_maximum_avx2(const std::int32_t* marks, std::size_t count, const float* in,
                                    std::size_t n, std::size_t rows, float* out) {
  if (rows == 4)
    for_each_block_avx2(marks, count, in, n, rows, out,
                        FloatBlocksAvx2<4>{in, n, rows, count, out});
  else
    for_each_block_avx2(marks, count, in, n, rows, out,
                        FloatBlocksAvx2<0>{in, n, rows, count, out});
}

#else

void gather_by_running_maximum_permute(const std::int32_t* marks, std::size_t count,
                                       const float* in, std::size_t n, std::size_t rows,
                                       float* out) {
  gather_by_running_maximum_scalar(marks, count, in, n, rows, out);
}

void gather_by_running_maximum_permute(const std::int32_t* marks, std::size_t count,
                                       const double* in, std::size_t n, std::size_t rows,
                                       double* out) {
  gather_by_running_maximum_scalar(marks, count, in, n, rows, out);
}

void gather_by_running_maximum_avx2(const std::int32_t* marks, std::size_t count, const float* in,
                                    std::size_t n, std::size_t rows, float* out) {
  gather_by_running_maximum_scalar(marks, count, in, n, rows, out);
}

#endif

void gather_by_running_maximum(const std::int32_t* marks, std::size_t count, const float* in,
                               std::size_t n, std::size_t rows, float* out) {
  if (gather_uses_permutes())
    gather_by_running_maximum_permute(marks, count, in, n, rows, out);
  else if (gather_uses_avx2())
    gather_by_running_maximum_avx2(marks, count, in, n, rows, out);
  else
    gather_by_running_maximum_scalar(marks, count, in, n, rows, out);
}

// Double rows: four to an AVX2 vector, the permutes and blends cost what the scalar copy does.
void gather_by_running_maximum(const std::int32_t* marks, std::size_t count, const double* in,
                               std::size_t n, std::size_t rows, double* out) {
  if (gather_uses_permutes())
    gather_by_running_maximum_permute(marks, count, in, n, rows, out);
  else
    gather_by_running_maximum_scalar(marks, count, in, n, rows, out);
}

}  // namespace opf::kernels
