#include "opf/particles/member_table_step.h"

#include "opf/particles/kernel_dispatch.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

#ifdef OPF_KERNEL_DISPATCH
#include <immintrin.h>
// GCC 12's intrinsics pass _mm512_undefined_epi32() as the unused merge source, which trips
// -Wmaybe-uninitialized where they are inlined (GCC bug 105593, fixed in GCC 13).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace opf::kernels {
namespace {

OPF_KERNEL void generic_step(double* __restrict x, const float* __restrict noise,
                             const std::uint8_t* __restrict member, const double* __restrict offset,
                             const double* __restrict spread, std::size_t count) {
#pragma omp simd
  for (std::size_t i = 0; i < count; ++i)
    x[i] += offset[member[i]] + spread[member[i]] * static_cast<double>(noise[i]);
}

#ifdef OPF_KERNEL_DISPATCH

// The tables' first kPermuteTableSize entries as four registers each: a member's low four bits
// pick a lane of a pair, its fifth bit the pair.
[[gnu::target("avx512f")]] void permute_step(double* __restrict x, const float* __restrict noise,
                                             const std::uint8_t* __restrict member,
                                             const double* offset, const double* spread,
                                             std::size_t count) {
  const __m512d o0 = _mm512_loadu_pd(offset), o1 = _mm512_loadu_pd(offset + 8),
                o2 = _mm512_loadu_pd(offset + 16), o3 = _mm512_loadu_pd(offset + 24);
  const __m512d s0 = _mm512_loadu_pd(spread), s1 = _mm512_loadu_pd(spread + 8),
                s2 = _mm512_loadu_pd(spread + 16), s3 = _mm512_loadu_pd(spread + 24);
  const __m512i second_pair = _mm512_set1_epi64(16);
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    long long bytes;
    std::memcpy(&bytes, member + i, sizeof bytes);
    const __m512i m = _mm512_cvtepu8_epi64(_mm_cvtsi64_si128(bytes));
    const __mmask8 upper = _mm512_test_epi64_mask(m, second_pair);
    const __m512d off = _mm512_mask_blend_pd(upper, _mm512_permutex2var_pd(o0, m, o1),
                                             _mm512_permutex2var_pd(o2, m, o3));
    const __m512d spr = _mm512_mask_blend_pd(upper, _mm512_permutex2var_pd(s0, m, s1),
                                             _mm512_permutex2var_pd(s2, m, s3));
    const __m512d e = _mm512_cvtps_pd(_mm256_loadu_ps(noise + i));
    _mm512_storeu_pd(x + i, _mm512_add_pd(_mm512_loadu_pd(x + i), _mm512_fmadd_pd(spr, e, off)));
  }
  for (; i < count; ++i)
    x[i] += std::fma(spread[member[i]], static_cast<double>(noise[i]), offset[member[i]]);
}

#endif

}  // namespace

bool member_step_uses_permutes(std::size_t members) {
  return members <= kPermuteTableSize && cpu_has_avx512f();
}

void add_member_offset_and_noise_generic(double* x, const float* noise, const std::uint8_t* member,
                                         const MemberTable& offset, const MemberTable& spread,
                                         std::size_t count) {
  generic_step(x, noise, member, offset.data(), spread.data(), count);
}

void add_member_offset_and_noise_permute(double* x, const float* noise, const std::uint8_t* member,
                                         const MemberTable& offset, const MemberTable& spread,
                                         std::size_t members, std::size_t count) {
  if (!member_step_uses_permutes(members))
    throw std::logic_error("add_member_offset_and_noise_permute: no AVX-512, or over 32 members");
#ifdef OPF_KERNEL_DISPATCH
  permute_step(x, noise, member, offset.data(), spread.data(), count);
#else
  (void)x, (void)noise, (void)member, (void)offset, (void)spread, (void)count;
#endif
}

void add_member_offset_and_noise(double* x, const float* noise, const std::uint8_t* member,
                                 const MemberTable& offset, const MemberTable& spread,
                                 std::size_t members, std::size_t count) {
#ifdef OPF_KERNEL_DISPATCH
  if (member_step_uses_permutes(members))
    return permute_step(x, noise, member, offset.data(), spread.data(), count);
#else
  (void)members;
#endif
  generic_step(x, noise, member, offset.data(), spread.data(), count);
}

}  // namespace opf::kernels
