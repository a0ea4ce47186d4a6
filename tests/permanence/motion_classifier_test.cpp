#include "permanence/motion_classifier.h"

#include "core/so3.h"

#include <gtest/gtest.h>

#include <vector>

namespace opf {
namespace {

std::vector<TrajectorySample> window_of(std::vector<Eigen::Vector3d> positions,
                                        std::vector<double> angles = {}) {
  std::vector<TrajectorySample> window;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const double angle = i < angles.size() ? angles[i] : 0.0;
    window.push_back(
        {static_cast<double>(i) / 30.0, positions[i], so3::exp(Eigen::Vector3d(0, 0, angle))});
  }
  return window;
}

TEST(MotionClassifier, StillWithinTheThresholdsIsStatic) {
  // Largest pairwise distance 9 mm < 1 cm; largest rotation 0.4 rad < 0.5 rad.
  const auto w = window_of({{0, 0, 0}, {0.005, 0, 0}, {-0.004, 0, 0}}, {0.0, 0.4, 0.2});
  EXPECT_EQ(classify_motion(w, MotionThresholds{}), Motion::kStatic);
}

TEST(MotionClassifier, UsesTheLargestPairwiseDistanceNotTheEndpoints) {
  // First and last samples coincide; the object went 1.2 cm away in between.
  const auto w = window_of({{0, 0, 0}, {0.012, 0, 0}, {0, 0, 0}});
  EXPECT_EQ(classify_motion(w, MotionThresholds{}), Motion::kMoving);
}

TEST(MotionClassifier, RotationAloneMakesItMoving) {
  const auto w = window_of({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, {0.0, 0.3, 0.6});
  EXPECT_EQ(classify_motion(w, MotionThresholds{}), Motion::kMoving);
}

TEST(MotionClassifier, RotationDistanceIsGeodesicAcrossPi) {
  // Yaw 3.0 and -3.0 are 0.28 rad apart on SO(3), not 6 rad as Euler differences would say.
  const auto w = window_of({{0, 0, 0}, {0, 0, 0}}, {3.0, -3.0});
  EXPECT_EQ(classify_motion(w, MotionThresholds{}), Motion::kStatic);
}

TEST(MotionClassifier, FewerThanTwoSamplesIsStatic) {
  EXPECT_EQ(classify_motion({}, MotionThresholds{}), Motion::kStatic);
  EXPECT_EQ(classify_motion(window_of({{1, 2, 3}}), MotionThresholds{}), Motion::kStatic);
}

}  // namespace
}  // namespace opf
