// The resampling kernels: indices that follow the cumulative weights, gathers.

#include "opf/particles/resampling_kernels.h"
#include "opf/core/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

namespace opf {
namespace {

// The textbook walk over the cumulative weights (the definition of systematic resampling).
std::vector<std::size_t> reference_systematic(const std::vector<double>& w, double offset) {
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  std::vector<std::size_t> indices;
  double cumulative = w[0] / total;
  std::size_t j = 0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    const double u = (static_cast<double>(k) + offset) / static_cast<double>(w.size());
    while (u >= cumulative && j + 1 < w.size()) cumulative += w[++j] / total;
    indices.push_back(j);
  }
  return indices;
}

TEST(ResamplingKernels, SystematicIndicesFollowTheCumulativeWeights) {
  Random random(1);
  for (std::size_t n : {2, 7, 100, 1001, 5000}) {
    std::vector<double> w(n);
    for (double& v : w) v = std::exp(-8.0 * random.uniform());  // spans three decades
    const double offset = random.uniform();
    std::vector<std::size_t> indices(n);
    kernels::systematic_indices(w.data(), n, offset, n, indices.data());
    const std::vector<std::size_t> expected = reference_systematic(w, offset);
    // Both walks add the same weights in a different order; a slot may change particle only
    // where a position falls within rounding of a boundary, which these draws never do.
    EXPECT_EQ(indices, expected) << n;
    std::vector<float> wf(w.begin(), w.end());
    kernels::systematic_indices(wf.data(), n, offset, n, indices.data());
    std::size_t differing = 0;
    const std::vector<std::size_t> expected_f =
        reference_systematic(std::vector<double>(wf.begin(), wf.end()), offset);
    for (std::size_t k = 0; k < n; ++k) differing += indices[k] != expected_f[k];
    EXPECT_EQ(differing, 0u) << n;
  }
}

// Stratified resampling by end marks equals the walk over positions (k + u_k) / count.
TEST(ResamplingKernels, StratifiedIndicesFollowTheCumulativeWeights) {
  Random random(7);
  for (std::size_t n : {2, 7, 100, 5000}) {
    std::vector<double> w(n), u(n);
    for (double& v : w) v = std::exp(-8.0 * random.uniform());
    for (double& v : u) v = random.uniform();
    const double total = std::accumulate(w.begin(), w.end(), 0.0);
    std::vector<std::size_t> expected;
    double cumulative = w[0] / total;
    std::size_t j = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double position = (static_cast<double>(k) + u[k]) / static_cast<double>(n);
      while (position >= cumulative && j + 1 < n) cumulative += w[++j] / total;
      expected.push_back(j);
    }
    std::vector<std::size_t> indices(n);
    kernels::stratified_indices(w.data(), n, u.data(), n, indices.data());
    EXPECT_EQ(indices, expected) << n;
  }
}

// The one-pass resampling copies exactly what the index walk selects.
TEST(ResamplingKernels, SystematicResampleCopiesTheSelectedParticles) {
  Random random(6);
  for (std::size_t n : {2, 9, 1000, 4099}) {
    std::vector<float> w(n);
    for (float& v : w) v = static_cast<float>(std::exp(-6.0 * random.uniform()));
    const double offset = random.uniform();
    std::vector<std::size_t> indices(n);
    kernels::systematic_indices(w.data(), n, offset, n, indices.data());
    std::vector<double> translation(3 * n), moved(3 * n), expected(3 * n);
    for (double& v : translation) v = random.normal();
    kernels::systematic_resample(w.data(), n, offset, translation.data(), 3, moved.data());
    kernels::gather_rows(translation.data(), n, 3, indices.data(), n, expected.data());
    EXPECT_EQ(moved, expected) << n;
    std::vector<float> rotation(4 * n), turned(4 * n), expected_rotation(4 * n);
    for (float& v : rotation) v = static_cast<float>(random.normal());
    kernels::systematic_resample(w.data(), n, offset, rotation.data(), 4, turned.data());
    kernels::gather_rows(rotation.data(), n, 4, indices.data(), n, expected_rotation.data());
    EXPECT_EQ(turned, expected_rotation) << n;
  }
}

TEST(ResamplingKernels, SystematicResamplingOfEqualWeightsKeepsEveryParticle) {
  std::vector<double> w(1000, 3.0);
  std::vector<std::size_t> indices(1000);
  kernels::systematic_indices(w.data(), w.size(), 0.37, w.size(), indices.data());
  for (std::size_t k = 0; k < indices.size(); ++k) EXPECT_EQ(indices[k], k);
  // One particle with all the weight takes every slot.
  std::vector<double> one(50, 0.0);
  one[17] = 1.0;
  kernels::systematic_indices(one.data(), one.size(), 0.5, 20, indices.data());
  for (std::size_t k = 0; k < 20; ++k) EXPECT_EQ(indices[k], 17u);
}

TEST(ResamplingKernels, GatherAndLargestIndex) {
  const std::vector<double> in{0, 1, 2, 3, 10, 11, 12, 13};  // two rows of four
  const std::vector<std::size_t> indices{3, 3, 0, 2, 1};
  std::vector<double> out(10);
  kernels::gather_rows(in.data(), 4, 2, indices.data(), indices.size(), out.data());
  EXPECT_EQ(out, (std::vector<double>{3, 3, 0, 2, 1, 13, 13, 10, 12, 11}));
  std::vector<std::size_t> many(1003, 4);
  many[777] = 901;
  EXPECT_EQ(kernels::largest_index(many.data(), many.size()), 901u);
}

}  // namespace
}  // namespace opf
