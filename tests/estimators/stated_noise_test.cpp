// A detection's stated extra noise (Detection::extra_noise, a partial view's): every estimator
// adds it in variance to its configured observation noise, so a detection that states itself
// unreliable moves the estimate less; the `paper` preset's OPF keeps Q of Eq. 5 alone.

#include "opf/core/estimator.h"
#include "opf/core/pose_conversion.h"
#include "opf/core/tracker.h"
#include "opf/estimators/registry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace opf {
namespace {

constexpr double kRate = 30.0;
constexpr int kStillFrames = 30;
constexpr double kJump = 0.03;       // m: the last detection lies 3 sigma off a still object
constexpr double kExtraNoise = 0.1;  // m: ten times the configured 0.01 m
constexpr int kParticles = 2000;

// The x estimate after a still object at the origin is detected kJump off, the last detection
// stating `extra_noise`.
double x_after_jump(const std::string& estimator, const EstimatorSettings& settings,
                    double extra_noise) {
  Tracker tracker(make_estimator_factory(estimator, settings), 7);
  for (int k = 0; k < kStillFrames; ++k)
    tracker.step(Frame{
        k / kRate, {{"box", make_pose(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity())}}});
  const Frame jump{
      kStillFrames / kRate,
      {{"box", make_pose(Eigen::Vector3d(kJump, 0.0, 0.0), Eigen::Quaterniond::Identity()),
        extra_noise}}};
  return tracker.step(jump).front().pose.mean.x();
}

EstimatorSettings few_particles() {
  EstimatorSettings settings;
  settings.pf.translation_particles = settings.pf.rotation_particles = kParticles;  // all three
  return settings;
}

TEST(StatedNoise, EveryEstimatorMovesLessForADetectionStatingItsNoise) {
  // With R = (1 cm)^2 a 3 cm jump moves a filter by K 3 cm, K = P / (P + R); stated 10 cm, R grows
  // 101-fold and K by about as much once P is below R. A tenth of the unstated move is a wide
  // margin for the particle filters' sampling.
  const EstimatorSettings settings = few_particles();
  for (const std::string& name : estimator_names()) {
    const double unstated = x_after_jump(name, settings, 0.0);
    const double stated = x_after_jump(name, settings, kExtraNoise);
    EXPECT_GT(unstated, 0.003) << name;  // the jump is followed at all
    EXPECT_LT(std::abs(stated), 0.1 * unstated) << name;
  }
}

TEST(StatedNoise, ThePaperRuleKeepsTheConfiguredNoise) {
  // opf.stated_noise: false (the `paper` preset): the same seed gives the same estimate whatever
  // the detection states.
  EstimatorSettings settings = few_particles();
  settings.opf.stated_noise = false;
  EXPECT_EQ(x_after_jump("opf", settings, kExtraNoise), x_after_jump("opf", settings, 0.0));
}

TEST(StatedNoise, NoneStatedIsTheConfiguredNoise) {
  // An extra noise of 0 changes nothing: every estimator gives bit-identical estimates with the
  // switch on and off.
  EstimatorSettings on = few_particles();
  EstimatorSettings off = on;
  off.opf.stated_noise = false;
  EXPECT_EQ(x_after_jump("opf", on, 0.0), x_after_jump("opf", off, 0.0));
}

TEST(StatedNoise, ReadsTheDetectionThePoseBelongsTo) {
  const Frame frame{
      0.0,
      {{"ball", make_pose(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()), 0.02},
       {"mug", make_pose(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()), 0.0}}};
  const EnsembleView view{frame, {}};
  EXPECT_EQ(stated_extra_noise(view, &frame.detections[0].pose), 0.02);
  EXPECT_EQ(stated_extra_noise(view, &frame.detections[1].pose), 0.0);
  const mrpt::poses::CPose3D elsewhere = frame.detections[0].pose;  // equal, but not the frame's
  EXPECT_EQ(stated_extra_noise(view, &elsewhere), 0.0);
  EXPECT_EQ(stated_extra_noise(view, nullptr), 0.0);
}

TEST(StatedNoise, AddsInVariance) {
  EXPECT_DOUBLE_EQ(observation_sigma(0.03, 0.04), 0.05);
  EXPECT_DOUBLE_EQ(observation_sigma(0.01, 0.0), 0.01);
}

}  // namespace
}  // namespace opf
