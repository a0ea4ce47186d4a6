#pragma once
// The one source of randomness of a filter or simulator: xoshiro256++ seeded through splitmix64,
// with uniform and Gaussian draws. Each filter owns one; nothing global, so the same seed gives
// bit-identical runs on any platform (std::normal_distribution is implementation-defined).

#include <cstdint>
#include <span>

namespace opf {

/// One step of splitmix64 (Vigna): advances `state` and returns a well-mixed 64-bit word. Seeds
/// the generators' states from a single seed.
std::uint64_t splitmix64(std::uint64_t& state);

/// Mixes a base seed with an index (an object's number, a run's number) into an independent seed.
std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t index);

class Random {
 public:
  explicit Random(std::uint64_t seed);

  /// 64 random bits.
  std::uint64_t next();
  /// Uniform in [0, 1), 53 bits of precision.
  double uniform();
  /// Standard normal N(0, 1).
  double normal();
  /// Fills `out` with standard normal samples (Box-Muller in pairs: cheaper than one at a time).
  void fill_normal(std::span<double> out);

 private:
  std::uint64_t s_[4];
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace opf
