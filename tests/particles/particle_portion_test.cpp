// A portion's own columns (an estimator's per-particle state) move with the states.

#include "opf/particles/particle_portion.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace opf {
namespace {

TranslationParticles numbered_portion() {
  TranslationParticles portion;
  portion.columns.resize(2, 0);
  portion.resize(4);
  for (Eigen::Index i = 0; i < 4; ++i) {
    portion.states.col(i) = Eigen::Vector3d(10.0 + double(i), 0.0, 0.0);
    portion.columns(0, i) = double(i);
    portion.columns(1, i) = 0.5 * double(i);
  }
  return portion;
}

TEST(ParticlePortion, ColumnsTravelWithTheStatesWhenResampled) {
  TranslationParticles portion = numbered_portion();
  portion.weights.log() << -1.0, -2.0, -3.0, -4.0;
  portion.resample({3, 3, 0});
  ASSERT_EQ(portion.size(), 3u);
  ASSERT_EQ(portion.columns.rows(), 2);
  ASSERT_EQ(portion.columns.cols(), 3);
  const std::vector<double> picked = {3.0, 3.0, 0.0};
  for (Eigen::Index k = 0; k < 3; ++k) {
    EXPECT_EQ(portion.states(0, k), 10.0 + picked[std::size_t(k)]);
    EXPECT_EQ(portion.columns(0, k), picked[std::size_t(k)]);
    EXPECT_EQ(portion.columns(1, k), 0.5 * picked[std::size_t(k)]);
  }
  EXPECT_TRUE(portion.weights.uniform());
}

TEST(ParticlePortion, ResizeKeepsTheColumnsAndRestartsThemAtZero) {
  TranslationParticles portion = numbered_portion();
  portion.resize(6);
  ASSERT_EQ(portion.columns.rows(), 2);
  ASSERT_EQ(portion.columns.cols(), 6);
  EXPECT_EQ(portion.columns.cwiseAbs().maxCoeff(), 0.0);
  // Without columns, none appear.
  TranslationParticles plain;
  plain.resize(5);
  EXPECT_EQ(plain.columns.rows(), 0);
}

TEST(ParticlePortion, TheOnePassSystematicResamplingLeavesColumnsToResample) {
  TranslationParticles portion = numbered_portion();
  EXPECT_THROW(portion.resample_systematic({1.0f, 1.0f, 1.0f, 1.0f}, 0.5), std::logic_error);
  TranslationParticles plain;
  plain.resize(4);
  plain.states.setZero();
  plain.states(0, 2) = 7.0;
  plain.resample_systematic({0.0f, 0.0f, 1.0f, 0.0f}, 0.5);  // every draw lands on particle 2
  EXPECT_EQ(plain.states.row(0).minCoeff(), 7.0);
}

}  // namespace
}  // namespace opf
