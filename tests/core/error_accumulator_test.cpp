#include "opf/core/error_accumulator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace opf {
namespace {

// The feedback module's default threshold on trace(Q~).
constexpr double kEpsilonSafe = 0.1;

Estimate estimate_at(double x, EstimateMode mode) {
  Estimate e;
  e.pose = mrpt::poses::CPose3DPDFGaussian(mrpt::poses::CPose3D(x, 0, 0, 0, 0, 0));
  e.mode = mode;
  return e;
}

TEST(ErrorAccumulator, MeansOverAllFramesAndOverUnobservedFrames) {
  ErrorAccumulator errors(kEpsilonSafe);
  const mrpt::poses::CPose3D truth(0, 0, 0, 0.1, 0, 0);
  errors.add(estimate_at(0.1, EstimateMode::kMeasured), truth);
  errors.add(estimate_at(0.3, EstimateMode::kPredicted), truth);
  errors.add(estimate_at(0.5, EstimateMode::kPredicted), truth);
  const RunErrors r = errors.result();
  EXPECT_EQ(r.frames, 3u);
  EXPECT_EQ(r.unobserved_frames, 2u);
  EXPECT_NEAR(r.translation, 0.3, 1e-15);
  EXPECT_NEAR(r.translation_unobserved, 0.4, 1e-15);
  EXPECT_NEAR(r.rotation_paper, 0.1, 1e-12);
  EXPECT_NEAR(r.rotation_geodesic, 0.1, 1e-12);
}

Estimate timed(double t, double x, EstimateMode mode, double variance, bool alert = false) {
  // A copy of a named string: assigning the literal trips GCC 12's -Wstringop-overflow at -O3.
  static const std::string kObject = "a";
  Estimate e = estimate_at(x, mode);
  e.object = kObject;
  e.t = t;
  e.pose.cov.setIdentity();
  e.pose.cov *= variance;
  // Any estimator's trace at epsilon_safe raises the alert.
  e.observation_trace = alert ? kEpsilonSafe : std::nextafter(kEpsilonSafe, 0.0);
  return e;
}

TEST(ErrorAccumulator, CalibrationAndTimeHiddenOverHiddenFrames) {
  ErrorAccumulator errors(kEpsilonSafe);
  const mrpt::poses::CPose3D truth(0, 0, 0, 0, 0, 0);
  errors.add(timed(0.0, 0.01, EstimateMode::kMeasured, 1e-4), truth);
  // Hidden: errors 0.1 and 0.3 m against a variance of 0.01 m^2: NEES 1 and 9.
  errors.add(timed(0.05, 0.1, EstimateMode::kPredicted, 0.01), truth);
  errors.add(timed(0.15, 0.3, EstimateMode::kPredicted, 0.01), truth);
  errors.add(timed(0.2, 0.02, EstimateMode::kMeasured, 1e-4), truth);
  const RunErrors r = errors.result();
  EXPECT_NEAR(r.nees_translation, (1.0 + 9.0) / 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(r.nees_rotation, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(r.inside95_translation, 0.5);  // 9 > 7.81
  EXPECT_DOUBLE_EQ(r.inside95_rotation, 1.0);
  ASSERT_EQ(r.hidden_profile.size(), 2u);
  EXPECT_NEAR(r.hidden_profile[0].translation, 0.1, 1e-15);
  EXPECT_NEAR(r.hidden_profile[1].translation, 0.3, 1e-15);
  EXPECT_EQ(r.reacquisition.gaps, 1u);
  EXPECT_NEAR(r.reacquisition.first_error, 0.02, 1e-15);
}

TEST(ErrorAccumulator, AlertPrecisionAndRecallAgainstTheAlertDistance) {
  ErrorAccumulator errors(kEpsilonSafe, 0.1);
  const mrpt::poses::CPose3D truth(0, 0, 0, 0, 0, 0);
  // Errors 0.05 (alert: false alarm), 0.2 (alert: hit), 0.3 (no alert: miss), 0.01 (quiet).
  errors.add(timed(0.0, 0.05, EstimateMode::kMeasured, 1e-4, true), truth);
  errors.add(timed(0.1, 0.2, EstimateMode::kPredicted, 1e-2, true), truth);
  errors.add(timed(0.2, 0.3, EstimateMode::kPredicted, 1e-2, false), truth);
  errors.add(timed(0.3, 0.01, EstimateMode::kMeasured, 1e-4, false), truth);
  const RunErrors r = errors.result();
  EXPECT_DOUBLE_EQ(r.alert_precision, 0.5);
  EXPECT_DOUBLE_EQ(r.alert_recall, 0.5);
  EXPECT_THROW(ErrorAccumulator(kEpsilonSafe, 0.0), std::invalid_argument);
  EXPECT_THROW(ErrorAccumulator(0.0), std::invalid_argument);
}

TEST(ErrorAccumulator, UndefinedScoresAreNaN) {
  ErrorAccumulator errors(kEpsilonSafe);
  errors.add(timed(0.0, 0.01, EstimateMode::kMeasured, 1e-4), mrpt::poses::CPose3D());
  const RunErrors r = errors.result();
  EXPECT_TRUE(std::isnan(r.nees_translation));  // no hidden frame
  EXPECT_TRUE(std::isnan(r.inside95_translation));
  EXPECT_TRUE(std::isnan(r.alert_precision));  // no alert
  EXPECT_TRUE(std::isnan(r.alert_recall));     // no error above 0.1 m
}

TEST(ErrorAccumulator, EmptyRunIsAnError) {
  EXPECT_THROW(ErrorAccumulator(kEpsilonSafe).result(), std::logic_error);
}

}  // namespace
}  // namespace opf
