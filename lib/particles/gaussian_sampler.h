#pragma once
// Standard normal samples in bulk, the dominant cost of a particle filter step (3 per particle
// per portion). Sixteen independent xoshiro256++ streams run side by side so the generator, the
// Box-Muller transform and its log/sin/cos vectorise; each 64-bit draw gives a pair of samples
// in single precision (24-bit uniforms: the tails are cut at 5.8 sigma, where a sample appears
// once in 10^8). The lanes are fixed at sixteen whatever the CPU, so the stream depends on the
// seed alone.

#include <array>
#include <cstdint>
#include <span>

namespace opf {

class GaussianSampler {
 public:
  static constexpr int kLanes = 16;
  /// Samples produced per round of the sixteen streams.
  static constexpr std::size_t kBlock = 2 * kLanes;

  explicit GaussianSampler(std::uint64_t seed);

  /// Fills `out` with independent N(0, 1) samples. The stream advances by whole blocks of kBlock,
  /// so the values depend on the lengths requested, not only on the count in total.
  void fill(std::span<float> out);

 private:
  // s_[word][lane]: xoshiro256++ state, lane-minor so the eight lanes sit in one vector.
  alignas(64) std::array<std::array<std::uint64_t, kLanes>, 4> s_;
};

}  // namespace opf
