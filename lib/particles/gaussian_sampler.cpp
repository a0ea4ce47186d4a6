#include "opf/particles/gaussian_sampler.h"

#include "opf/core/random.h"
#include "opf/particles/kernel_dispatch.h"
#include "opf/particles/vector_math.h"

#include <cmath>
#include <cstring>

namespace opf {
namespace {

OPF_ALWAYS_INLINE std::uint64_t rotl(std::uint64_t x, int k) {
  return (x << k) | (x >> (64 - k));
}

using State = std::array<std::array<std::uint64_t, GaussianSampler::kLanes>, 4>;

// One round: sixteen 64-bit draws, one per lane, turned into 32 samples. The top 24 bits make the
// radius' uniform in (0, 1]; the next 24 the angle: two bits pick the quadrant, 22 the angle in
// it, so sin and cos need polynomials on [-pi/4, pi/4] only.
OPF_ALWAYS_INLINE void normal_block(State& s, float* out) {
  constexpr int kLanes = GaussianSampler::kLanes;
  for (int l = 0; l < kLanes; ++l) {
    const std::uint64_t r = rotl(s[0][l] + s[3][l], 23) + s[0][l];
    const std::uint64_t t = s[1][l] << 17;
    s[2][l] ^= s[0][l];
    s[3][l] ^= s[1][l];
    s[1][l] ^= s[2][l];
    s[0][l] ^= s[3][l];
    s[2][l] ^= t;
    s[3][l] = rotl(s[3][l], 45);

    const auto radius_bits = static_cast<std::int32_t>(r >> 40);
    const auto angle_bits = static_cast<std::int32_t>((r >> 16) & 0xffffff);
    const float u = (static_cast<float>(radius_bits) + 1.0f) * 0x1.0p-24f;
    const float radius = std::sqrt(-2.0f * vmath::log_positive(u));
    // The angle q pi/2 + x with x uniform in [-pi/4, pi/4): uniform on the circle (a turn by
    // -pi/4 of the usual [0, 2 pi)), and sin x, cos x need the short polynomials only.
    const std::int32_t quadrant = angle_bits >> 22;
    const float x = (static_cast<float>(angle_bits & 0x3fffff) + 0.5f) *
                        static_cast<float>(vmath::kHalfPi * 0x1.0p-22) -
                    static_cast<float>(vmath::kQuarterPi);
    float sin_x, cos_x;
    vmath::sincos_reduced(x, sin_x, cos_x);
    // Rotating by the quadrant: (sin, cos) of x + q pi / 2.
    const bool odd = (quadrant & 1) != 0;
    const float a = odd ? cos_x : sin_x;
    const float b = odd ? sin_x : cos_x;
    out[l] = radius * ((quadrant & 2) != 0 ? -a : a);
    out[kLanes + l] = radius * ((quadrant == 1 || quadrant == 2) ? -b : b);
  }
}

OPF_KERNEL void fill_blocks(State& state, float* __restrict out, std::size_t blocks) {
  // A local copy of the state lives in registers through the loop; the member is written once.
  State s = state;
  for (std::size_t k = 0; k < blocks; ++k) normal_block(s, out + k * GaussianSampler::kBlock);
  state = s;
}

}  // namespace

GaussianSampler::GaussianSampler(std::uint64_t seed) {
  std::uint64_t state = seed ^ 0x6a09e667f3bcc909ULL;  // apart from Random's use of the seed
  for (auto& word : s_)
    for (auto& lane : word) lane = splitmix64(state);
}

void GaussianSampler::fill(std::span<float> out) {
  const std::size_t whole = out.size() / kBlock;
  fill_blocks(s_, out.data(), whole);
  const std::size_t rest = out.size() - whole * kBlock;
  if (rest == 0) return;
  alignas(64) float tail[kBlock];
  fill_blocks(s_, tail, 1);
  std::memcpy(out.data() + whole * kBlock, tail, rest * sizeof(float));
}

}  // namespace opf
