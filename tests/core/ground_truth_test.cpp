#include "opf/core/ground_truth.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

// The truth of one object at `times`: moving at (1, -0.5, 0.2) m/s from the origin, turning at
// 2 rad/s about a fixed tilted axis, so that linear interpolation and slerp are exact.
Eigen::Vector3d position_at(double t) {
  return Eigen::Vector3d(1.0, -0.5, 0.2) * t;
}
Eigen::Quaterniond orientation_at(double t) {
  return so3::exp(2.0 * t * Eigen::Vector3d(1.0, 2.0, 2.0).normalized());
}

std::vector<Frame> truth_at(const std::vector<double>& times, const std::string& object = "cup") {
  std::vector<Frame> frames;
  for (double t : times) {
    Frame frame;
    frame.t = t;
    frame.detections.push_back({object, make_pose(position_at(t), orientation_at(t))});
    frames.push_back(frame);
  }
  return frames;
}

double position_error(const mrpt::poses::CPose3D& pose, double t) {
  return (translation_of(pose) - position_at(t)).norm();
}
double rotation_error(const mrpt::poses::CPose3D& pose, double t) {
  return orientation_of(pose).angularDistance(orientation_at(t));
}

TEST(GroundTruth, AnEstimateBetweenRowsTakesTheTruthInterpolatedAtItsTime) {
  // Rows every 10 ms; an estimate 3.3 ms after a row, where the nearest row is 3.3 mm and
  // 6.6 mrad off the motion.
  const GroundTruth truth(truth_at({0.00, 0.01, 0.02, 0.03}), 0.005);
  for (double t : {0.0033, 0.0150, 0.0299}) {
    const auto pose = truth.at("cup", t);
    ASSERT_TRUE(pose.has_value()) << t;
    EXPECT_LT(position_error(*pose, t), 1e-12) << t;
    EXPECT_LT(rotation_error(*pose, t), 1e-9) << t;
  }
  // A row's own time gives the row as it is.
  const auto row = truth.at("cup", 0.02);
  ASSERT_TRUE(row.has_value());
  EXPECT_EQ(translation_of(*row), position_at(0.02));
}

TEST(GroundTruth, ADropoutOfTheTruthIsNotBridged) {
  // Rows every 10 ms, none from 0.03 to 0.10 s: more than twice the median interval apart.
  const GroundTruth truth(truth_at({0.00, 0.01, 0.02, 0.03, 0.10, 0.11, 0.12}), 0.004);
  EXPECT_FALSE(truth.at("cup", 0.06).has_value());
  EXPECT_NE(truth.missing("cup", 0.06).find("a dropout of the truth: no rows from 0.03 to 0.1 s"),
            std::string::npos)
      << truth.missing("cup", 0.06);
  // Within the tolerance of a row at the dropout's edge, that row serves.
  ASSERT_TRUE(truth.at("cup", 0.033).has_value());
  EXPECT_EQ(translation_of(*truth.at("cup", 0.033)), position_at(0.03));
  // A row missing now and then is bridged: 20 ms is twice the median interval.
  const GroundTruth sparse(truth_at({0.00, 0.01, 0.02, 0.04, 0.05, 0.06}), 0.0);
  ASSERT_TRUE(sparse.at("cup", 0.03).has_value());
  EXPECT_LT(position_error(*sparse.at("cup", 0.03), 0.03), 1e-12);
}

TEST(GroundTruth, BeyondItsRowsARowWithinTheToleranceServes) {
  const GroundTruth truth(truth_at({0.10, 0.11, 0.12}), 0.004);
  ASSERT_TRUE(truth.at("cup", 0.097).has_value());
  EXPECT_EQ(translation_of(*truth.at("cup", 0.097)), position_at(0.10));
  EXPECT_FALSE(truth.at("cup", 0.095).has_value());
  EXPECT_FALSE(truth.at("cup", 0.125).has_value());
  EXPECT_NE(
      truth.missing("cup", 0.125)
          .find("(its rows run from 0.1 to 0.12 s; beyond them a row within 0.004 s is taken)"),
      std::string::npos)
      << truth.missing("cup", 0.125);
  EXPECT_NE(truth.missing("cups", 0.11)
                .find("the truth has no such object (its objects: cup); did you mean 'cup'?"),
            std::string::npos)
      << truth.missing("cups", 0.11);
}

TEST(GroundTruth, RefusesANegativeTolerance) {
  EXPECT_THROW(GroundTruth(truth_at({0.0}), -1.0), std::invalid_argument);
  EXPECT_THROW(GroundTruth(truth_at({0.0}), std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace opf
