#include "opf/particles/member_table_step.h"

#include "opf/core/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

struct Step {
  std::vector<double> x;
  std::vector<float> noise;
  std::vector<std::uint8_t> member;
  kernels::MemberTable offset{}, spread{};
};

Step random_step(std::size_t members, std::size_t count, Random& random) {
  Step s;
  for (std::size_t j = 0; j < members; ++j) {
    s.offset[j] = random.normal();
    s.spread[j] = std::abs(random.normal());
  }
  for (std::size_t i = 0; i < count; ++i) {
    s.x.push_back(10.0 * random.normal());
    s.noise.push_back(static_cast<float>(random.normal()));
    s.member.push_back(static_cast<std::uint8_t>(random.uniform() * static_cast<double>(members)));
  }
  return s;
}

bool cpu_has_avx512f() {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(OPF_NO_DISPATCH)
  return __builtin_cpu_supports("avx512f") != 0;
#else
  return false;
#endif
}

// Every particle moves by its own member's entries (to the rounding of one fused multiply-add or
// of a multiply and an add, as the CPU's version compiles it), whichever path runs; tables of 1 to
// 48 members cover one register pair, both pairs, and the generic path's; counts off a multiple of
// eight leave a scalar tail.
TEST(MemberTableStep, EachParticleMovesByItsMembersOffsetAndSpread) {
  Random random(21);
  for (const std::size_t members : {1u, 3u, 15u, 16u, 17u, 18u, 31u, 32u, 48u})
    for (const std::size_t count : {0u, 1u, 7u, 8u, 9u, 1000u, 1027u}) {
      const Step s = random_step(members, count, random);
      std::vector<double> x = s.x;
      kernels::add_member_offset_and_noise(x.data(), s.noise.data(), s.member.data(), s.offset,
                                           s.spread, members, count);
      for (std::size_t i = 0; i < count; ++i) {
        const double expected =
            s.x[i] +
            std::fma(s.spread[s.member[i]], static_cast<double>(s.noise[i]), s.offset[s.member[i]]);
        ASSERT_NEAR(x[i], expected, 4e-15 * (std::abs(expected) + 1.0))
            << members << " members, particle " << i << " of " << count;
      }
    }
}

// On a CPU with AVX-512 the permute path runs for up to 32 members: x_i plus one fused
// multiply-add, exactly, which is what the generic loop compiles to at -O3 there (a release
// build's seeded results do not depend on the path; a -O1 build rounds the product apart).
TEST(MemberTableStep, ThePermutePathAddsOneFusedMultiplyAdd) {
  if (!cpu_has_avx512f()) GTEST_SKIP() << "the permute path needs AVX-512";
  Random random(22);
  for (const std::size_t members : {1u, 2u, 15u, 16u, 17u, 18u, 31u, 32u})
    for (const std::size_t count : {1u, 8u, 13u, 1024u, 1031u}) {
      const Step s = random_step(members, count, random);
      std::vector<double> expected = s.x, permuted = s.x;
      for (std::size_t i = 0; i < count; ++i)
        expected[i] +=
            std::fma(s.spread[s.member[i]], static_cast<double>(s.noise[i]), s.offset[s.member[i]]);
      kernels::add_member_offset_and_noise_permute(permuted.data(), s.noise.data(), s.member.data(),
                                                   s.offset, s.spread, members, count);
      EXPECT_EQ(permuted, expected) << members << " members, " << count << " particles";
    }
}

TEST(MemberTableStep, PermutesUpToThirtyTwoMembersWhereTheCpuHasAvx512) {
  EXPECT_EQ(kernels::member_step_uses_permutes(1), cpu_has_avx512f());
  EXPECT_EQ(kernels::member_step_uses_permutes(kernels::kPermuteTableSize), cpu_has_avx512f());
  EXPECT_FALSE(kernels::member_step_uses_permutes(kernels::kPermuteTableSize + 1));
  // Asked for directly where it cannot run, the permute path refuses.
  Random random(23);
  const Step s = random_step(kernels::kPermuteTableSize + 1, 8, random);
  std::vector<double> x = s.x;
  EXPECT_THROW(kernels::add_member_offset_and_noise_permute(x.data(), s.noise.data(),
                                                            s.member.data(), s.offset, s.spread,
                                                            kernels::kPermuteTableSize + 1, 8),
               std::logic_error);
}

}  // namespace
}  // namespace opf
