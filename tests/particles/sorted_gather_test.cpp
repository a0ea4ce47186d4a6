#include "opf/particles/sorted_gather.h"

#include "opf/core/random.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <type_traits>
#include <vector>

namespace opf {
namespace {

// Marks whose running maximum advances by a random step from {0, ..., max_step} per slot (the
// step is written as a mark only when it moves), capped at n - 1.
std::vector<std::int32_t> random_marks(std::size_t count, std::size_t n, int max_step,
                                       Random& random) {
  std::vector<std::int32_t> marks(count, 0);
  std::int32_t particle = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const auto step = static_cast<std::int32_t>(random.uniform() * (max_step + 1));
    const std::int32_t next =
        std::min<std::int32_t>(particle + step, static_cast<std::int32_t>(n) - 1);
    if (next != particle || random.uniform() < 0.5) marks[k] = next;  // repeats may be marked
    particle = next;
  }
  return marks;
}

bool cpu_has_avx2() {
#if defined(__x86_64__) && defined(__GNUC__)
  return __builtin_cpu_supports("avx2") != 0;
#else
  return false;
#endif
}

template <class T>
std::vector<T> expected_gather(const std::vector<std::int32_t>& marks, const std::vector<T>& in,
                               std::size_t n, std::size_t rows) {
  const std::size_t count = marks.size();
  std::vector<T> out(rows * count);
  std::int32_t particle = 0;
  for (std::size_t k = 0; k < count; ++k) {
    particle = std::max(particle, marks[k]);
    for (std::size_t r = 0; r < rows; ++r) out[r * count + k] = in[r * n + particle];
  }
  return out;
}

template <class T>
void expect_both_paths_match(std::size_t count, std::size_t n, std::size_t rows, int max_step,
                             Random& random) {
  const std::vector<std::int32_t> marks = random_marks(count, n, max_step, random);
  std::vector<T> in(rows * n);
  for (T& v : in) v = static_cast<T>(random.normal());
  const std::vector<T> expected = expected_gather(marks, in, n, rows);
  std::vector<T> scalar(rows * count), permuted(rows * count), chosen(rows * count);
  kernels::gather_by_running_maximum_scalar(marks.data(), count, in.data(), n, rows, scalar.data());
  kernels::gather_by_running_maximum(marks.data(), count, in.data(), n, rows, chosen.data());
  EXPECT_EQ(scalar, expected) << "scalar, count " << count << ", n " << n << ", step " << max_step;
  EXPECT_EQ(chosen, expected);
  // The AVX2 path (float rows) runs wherever the CPU has AVX2 (the machines the tests run on
  // do), whichever path the dispatch chooses.
  if constexpr (std::is_same_v<T, float>) {
    if (cpu_has_avx2()) {
      std::vector<float> avx2(rows * count);
      kernels::gather_by_running_maximum_avx2(marks.data(), count, in.data(), n, rows, avx2.data());
      EXPECT_EQ(avx2, expected) << "avx2, count " << count << ", n " << n << ", step " << max_step;
    }
  }
  // The permute path's AVX-512 instructions exist only on CPUs that have them.
  if (!kernels::gather_uses_permutes()) return;
  kernels::gather_by_running_maximum_permute(marks.data(), count, in.data(), n, rows,
                                             permuted.data());
  EXPECT_EQ(permuted, expected) << "permute, count " << count << ", n " << n << ", step "
                                << max_step;
}

// Steps of up to 1 keep every block of sixteen slots in a 32-particle window (the permute), and
// of eight in a 16-particle one (AVX2); steps of up to 5 leave many blocks wider (the scalar
// fallback); counts off the block size leave a scalar tail; n close to count puts windows against
// the end of a row (masked loads).
TEST(SortedGather, BothPathsCopyTheRunningMaximumsParticles) {
  Random random(11);
  for (const std::size_t count : {1u, 15u, 16u, 17u, 33u, 1000u, 5003u})
    for (const int max_step : {0, 1, 2, 5})
      for (const std::size_t rows : {1u, 3u, 4u}) {
        const std::size_t n = count + 2;
        expect_both_paths_match<float>(count, n, rows, max_step, random);
        expect_both_paths_match<double>(count, n, rows, max_step, random);
        expect_both_paths_match<float>(count, 7 * count + 40, rows, max_step, random);
        expect_both_paths_match<double>(count, 7 * count + 40, rows, max_step, random);
      }
}

// A row shorter than a window: the loads past its end must be masked off (AddressSanitizer
// would report them) and the copy still exact.
TEST(SortedGather, WindowsAtTheEndOfShortRows) {
  Random random(12);
  for (const std::size_t n : {1u, 2u, 9u, 17u, 31u})
    for (const std::size_t rows : {3u, 4u}) {
      expect_both_paths_match<float>(48, n, rows, 1, random);
      expect_both_paths_match<double>(48, n, rows, 1, random);
    }
}

// The permute path is what the filters run on CPUs with AVX-512 (the benchmark reports'
// machine); elsewhere the scalar path serves alone.
TEST(SortedGather, PermutesWhereverTheCpuHasAvx512) {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(OPF_NO_DISPATCH)
  EXPECT_EQ(kernels::gather_uses_permutes(), __builtin_cpu_supports("avx512f") != 0);
#else
  EXPECT_FALSE(kernels::gather_uses_permutes());
#endif
}

// Without AVX-512, a CPU with AVX2 takes the AVX2 path; never both.
TEST(SortedGather, TakesTheAvx2PathWhereTheCpuHasAvx2ButNotAvx512) {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(OPF_NO_DISPATCH)
  EXPECT_EQ(kernels::gather_uses_avx2(),
            __builtin_cpu_supports("avx2") != 0 && __builtin_cpu_supports("avx512f") == 0);
#else
  EXPECT_FALSE(kernels::gather_uses_avx2());
#endif
  EXPECT_FALSE(kernels::gather_uses_avx2() && kernels::gather_uses_permutes());
}

}  // namespace
}  // namespace opf
