#include "opf/sim/noisy_measurement.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opf::sim {
namespace {

SceneSnapshot two_bodies() {
  SceneSnapshot s;
  s.bodies.resize(2);
  s.bodies[0].name = "ball";
  s.bodies[1].name = "mug";
  s.poses = {BodyPose{{0.4, 0.0, 0.0}, so3::exp(Eigen::Vector3d(0, 0, 0.3))},
             BodyPose{{0.4, 0.15, 0.03}, Eigen::Quaterniond::Identity()}};
  return s;
}

TEST(NoisyMeasurement, OnlyBodiesSeenWellEnoughAreMeasured) {
  CameraFrame camera{1.0,
                     {{"ball", 0.2, true, {0.4, 0.0, 0.0}}, {"mug", 0.9, true, {0.4, 0.15, 0.03}}}};
  MeasurementSettings settings;  // min_visible_fraction 0.3
  Random noise(1);
  const Frame f = noisy_measurement(camera, two_bodies(), settings, noise);
  EXPECT_EQ(f.t, 1.0);
  ASSERT_EQ(f.detections.size(), 1u);
  EXPECT_EQ(f.detections[0].object, "mug");
  camera.sightings[1].detected = false;
  EXPECT_TRUE(noisy_measurement(camera, two_bodies(), settings, noise).detections.empty());
}

TEST(NoisyMeasurement, APartialViewStatesItsOffsetAsExtraNoise) {
  CameraFrame camera{
      1.0,
      {{"ball", 0.5, true, {0.4, 0.0, 0.0}, 0.0125}, {"mug", 1.0, true, {0.4, 0.15, 0.03}, 0.0}}};
  Random noise(1);
  const Frame f = noisy_measurement(camera, two_bodies(), MeasurementSettings{}, noise);
  ASSERT_EQ(f.detections.size(), 2u);
  EXPECT_EQ(f.detections[0].extra_noise, 0.0125);
  EXPECT_EQ(f.detections[1].extra_noise, 0.0);
}

TEST(NoisyMeasurement, EveryDetectionStatesItsSilhouettesRadius) {
  CameraFrame camera{1.0,
                     {{"ball", 0.5, true, {0.4, 0.0, 0.0}, 0.0125, 0.025},
                      {"mug", 1.0, true, {0.4, 0.15, 0.03}, 0.0, 0.045}}};
  Random noise(1);
  const Frame f = noisy_measurement(camera, two_bodies(), MeasurementSettings{}, noise);
  ASSERT_EQ(f.detections.size(), 2u);
  EXPECT_EQ(f.detections[0].radius, 0.025);
  EXPECT_EQ(f.detections[1].radius, 0.045);
}

TEST(NoisyMeasurement, ADetectorThatStatesNoSizesGivesThePoseAndPartialViewAlone) {
  CameraFrame camera{
      1.0,
      {{"ball", 0.5, true, {0.4, 0.0, 0.0}, 0.0125, 0.025, Eigen::Vector3d(0.05, 0.05, 0.05)}}};
  MeasurementSettings settings;
  settings.state_sizes = false;
  Random sized_noise(1), unsized_noise(1);
  const Frame sized = noisy_measurement(camera, two_bodies(), MeasurementSettings{}, sized_noise);
  const Frame unsized = noisy_measurement(camera, two_bodies(), settings, unsized_noise);
  ASSERT_EQ(sized.detections.size(), 1u);
  ASSERT_EQ(unsized.detections.size(), 1u);
  EXPECT_EQ(sized.detections[0].radius, 0.025);
  EXPECT_EQ(sized.detections[0].box, Eigen::Vector3d(0.05, 0.05, 0.05));
  EXPECT_EQ(unsized.detections[0].radius, 0.0);
  EXPECT_EQ(unsized.detections[0].box, Eigen::Vector3d::Zero());
  // The same draws: only the sizes differ.
  EXPECT_EQ(unsized.detections[0].extra_noise, 0.0125);
  EXPECT_EQ(unsized.detections[0].pose.asVectorVal(), sized.detections[0].pose.asVectorVal());
}

TEST(NoisyMeasurement, NoiseHasTheConfiguredSpread) {
  // Over many frames the position noise has std 2 mm per axis and the orientation noise 0.01 rad
  // per tangent axis around the truth: 5 standard errors of the variance estimate (sqrt(2/N)).
  const CameraFrame camera{0.0, {{"ball", 1.0, true, {0.4, 0.0, 0.0}}}};
  MeasurementSettings settings;
  Random noise(2);
  constexpr int kN = 20000;
  double position_var = 0.0, rotation_var = 0.0;
  const SceneSnapshot truth = two_bodies();
  for (int k = 0; k < kN; ++k) {
    const Frame f = noisy_measurement(camera, truth, settings, noise);
    position_var +=
        (translation_of(f.detections[0].pose) - Eigen::Vector3d(0.4, 0, 0)).squaredNorm() / 3;
    rotation_var +=
        so3::difference(truth.poses[0].orientation, orientation_of(f.detections[0].pose))
            .squaredNorm() /
        3;
  }
  const double tolerance = 5.0 * std::sqrt(2.0 / (3 * kN));
  EXPECT_NEAR(position_var / kN / (0.002 * 0.002), 1.0, tolerance);
  EXPECT_NEAR(rotation_var / kN / (0.01 * 0.01), 1.0, tolerance);
}

TEST(NoisyMeasurement, OneBodysVisibilityDoesNotShiftAnothersNoise) {
  MeasurementSettings settings;
  CameraFrame seen{0.0, {{"ball", 1.0, true, {0.4, 0, 0}}, {"mug", 1.0, true, {0.4, 0.15, 0.03}}}};
  CameraFrame hidden = seen;
  hidden.sightings[0].detected = false;
  Random a(3), b(3);
  const Frame with = noisy_measurement(seen, two_bodies(), settings, a);
  const Frame without = noisy_measurement(hidden, two_bodies(), settings, b);
  EXPECT_EQ(with.detections[1].pose.asVectorVal(), without.detections[0].pose.asVectorVal());
}

}  // namespace
}  // namespace opf::sim
