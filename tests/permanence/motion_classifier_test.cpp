#include "opf/permanence/motion_classifier.h"

#include "opf/core/so3.h"

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

// The fitted-displacement test (which general_op uses): 30 samples with alternating +-4 mm
// jitter, optionally drifting, and the last three optionally biased 1.5 cm towards the object's
// visible side (a half-covered centroid).
std::vector<TrajectorySample> jittered_window(double drift_per_sample, double end_bias) {
  std::vector<Eigen::Vector3d> positions;
  for (int i = 0; i < 30; ++i) {
    const double jitter = (i % 2 == 0 ? 1.0 : -1.0) * 0.004;
    const double bias = i >= 27 ? end_bias : 0.0;
    positions.emplace_back(drift_per_sample * i + jitter + bias, 0.0, 0.0);
  }
  return window_of(positions);
}

Motion fitted(const std::vector<TrajectorySample>& w) {
  const TrajectoryModel line = fit_trajectory(w, TrajectoryFitOptions{});
  return classify_fitted_motion(line, w.front().t, w.back().t, MotionThresholds{});
}

TEST(MotionClassifier, FittedDisplacementIgnoresJitterAndABiasedEnd) {
  // Pairwise the bias reads as 1.9 cm of motion; the line through 30 samples, 3 of them biased,
  // moves by 6.2 mm over the window (the Huber loss, linear beyond 1 cm, tempers the pull).
  const auto w = jittered_window(0.0, 0.015);
  EXPECT_EQ(classify_motion(w, MotionThresholds{}), Motion::kMoving);
  EXPECT_EQ(fitted(w), Motion::kStatic);
}

TEST(MotionClassifier, FittedDisplacementSeesADriftThePairwiseTestCannotTellFromJitter) {
  // 0.6 mm per sample: 1.74 cm over the window, moving by either test.
  EXPECT_EQ(fitted(jittered_window(0.0006, 0.0)), Motion::kMoving);
  // 0.2 mm per sample: 0.58 cm, under the 1 cm threshold for the fit; pairwise, the 8 mm of
  // jitter on top make it 1.4 cm, "moving".
  const auto slow = jittered_window(0.0002, 0.0);
  EXPECT_EQ(fitted(slow), Motion::kStatic);
  EXPECT_EQ(classify_motion(slow, MotionThresholds{}), Motion::kMoving);
}

TEST(MotionClassifier, FittedDisplacementSeesATurn) {
  // Still in position, turning 0.02 rad per sample: 0.58 rad over the window (> 0.5 rad).
  std::vector<Eigen::Vector3d> positions(30, Eigen::Vector3d::Zero());
  std::vector<double> angles;
  for (int i = 0; i < 30; ++i) angles.push_back(0.02 * i);
  const auto w = window_of(positions, angles);
  const TrajectoryModel model = fit_trajectory(w, TrajectoryFitOptions{});
  EXPECT_EQ(classify_fitted_motion(model, w.front().t, w.back().t, MotionThresholds{}),
            Motion::kMoving);
  MotionThresholds looser;
  looser.rotation = 0.6;
  EXPECT_EQ(classify_fitted_motion(model, w.front().t, w.back().t, looser), Motion::kStatic);
}

}  // namespace
}  // namespace opf
