#include "opf/vision/blob_pose.h"

#include "opf/vision/object_segmenter.h"
#include "vision/synthetic_image.h"

#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace opf::vision {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

/// The sighting of a yellow rectangle drawn on a plain frame, found by the segmenter.
BlobSighting sighting_of(std::size_t frame, cv::Point2d centre, cv::Size2d size, double angle_deg) {
  cv::Mat image = test::plain_frame();
  test::draw_rectangle(image, centre, size, angle_deg, test::kYellow);
  SegmenterOptions options;
  options.hsv = {{20, 100, 100}, {40, 255, 255}};
  const auto blob = ObjectSegmenter(options).segment(image, frame);
  if (!blob) throw std::logic_error("the test rectangle was not found");
  return {frame, blob->centroid_px, blob->area_px, principal_axis_angle(blob->moments)};
}

TEST(VisionBlobPose, PrincipalAxisOfRotatedRectangles) {
  for (const double degrees : {-80.0, -45.0, -10.0, 0.0, 10.0, 30.0, 45.0, 80.0, 89.0}) {
    cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
    test::draw_rectangle(mask, {320.0, 240.0}, {240.0, 60.0}, degrees, cv::Scalar(255));
    EXPECT_NEAR(principal_axis_angle(cv::moments(mask, true)), degrees * kDeg, 0.01) << degrees;
  }
}

TEST(VisionBlobPose, PrincipalAxisIsInMinusToPlusHalfPi) {
  // The same rectangle turned by 100 degrees has its axis at -80 degrees: a line has no direction.
  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
  test::draw_rectangle(mask, {320.0, 240.0}, {240.0, 60.0}, 100.0, cv::Scalar(255));
  EXPECT_NEAR(principal_axis_angle(cv::moments(mask, true)), -80.0 * kDeg, 0.01);
}

TEST(VisionBlobPose, UnwrapHalfTurnPicksTheNearestEquivalentAngle) {
  EXPECT_DOUBLE_EQ(unwrap_half_turn(0.2, 0.1), 0.2);
  EXPECT_DOUBLE_EQ(unwrap_half_turn(-1.5, 1.5), -1.5 + kPi);  // across +pi/2
  EXPECT_DOUBLE_EQ(unwrap_half_turn(1.5, -1.5), 1.5 - kPi);   // across -pi/2
  EXPECT_DOUBLE_EQ(unwrap_half_turn(0.1, 2.0 * kPi + 0.05), 0.1 + 2.0 * kPi);
  EXPECT_DOUBLE_EQ(unwrap_half_turn(-1.0, -7.0), -1.0 - 2.0 * kPi);
}

TEST(VisionBlobPose, AngleIsUnwrappedAcrossTheHalfTurnAmbiguity) {
  // A rectangle turning steadily from 0 to 200 degrees in 10 degree steps: its principal axis
  // jumps from +90 to -80 degrees and from +80 to -90, the pose's angle does not.
  std::vector<BlobSighting> sightings;
  for (std::size_t k = 0; k <= 20; ++k)
    sightings.push_back(
        sighting_of(k, {320.0, 240.0}, {200.0, 60.0}, 10.0 * static_cast<double>(k)));
  EXPECT_LT(sightings[10].axis_angle - sightings[8].axis_angle, -2.5);  // the raw jump
  const auto poses = blob_poses(sightings, {});
  ASSERT_EQ(poses.size(), sightings.size());
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const double expected = 10.0 * static_cast<double>(k) * kDeg;
    EXPECT_NEAR(poses[k].angle, expected, 0.01) << k;
    // A rotation about z by the angle, written with w >= 0.
    EXPECT_EQ(poses[k].orientation.x(), 0.0);
    EXPECT_EQ(poses[k].orientation.y(), 0.0);
    EXPECT_GE(poses[k].orientation.w(), 0.0);
    EXPECT_NEAR(poses[k].orientation.angularDistance(
                    Eigen::Quaterniond(Eigen::AngleAxisd(expected, Eigen::Vector3d::UnitZ()))),
                0.0, 0.02)
        << k;
  }
  // Back the other way, from 20 degrees down to -200: unwrapped downwards.
  std::vector<BlobSighting> backwards;
  for (int k = 0; k <= 22; ++k)
    backwards.push_back(
        sighting_of(static_cast<std::size_t>(k), {320.0, 240.0}, {200.0, 60.0}, 20.0 - 10.0 * k));
  const auto down = blob_poses(backwards, {});
  EXPECT_NEAR(down.back().angle, -200.0 * kDeg, 0.01);
}

TEST(VisionBlobPose, DepthHalvesWhenTheBlobDoublesInSize) {
  std::vector<BlobSighting> sightings = {
      sighting_of(0, {320.0, 240.0}, {200.0, 80.0}, 20.0),
      sighting_of(1, {320.0, 240.0}, {400.0, 160.0}, 20.0),  // twice as close: 4 times the area
      sighting_of(2, {320.0, 240.0}, {100.0, 40.0}, 20.0),   // twice as far
  };
  BlobPoseOptions options;
  options.reference_frames = 1;  // the first sighting is at reference_depth
  options.reference_depth = 1.5;
  const auto poses = blob_poses(sightings, options);
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_DOUBLE_EQ(poses[0].position.z(), 1.5);
  EXPECT_NEAR(poses[1].position.z() / poses[0].position.z(), 0.5, 0.005);
  EXPECT_NEAR(poses[2].position.z() / poses[0].position.z(), 2.0, 0.02);
  // A given reference area overrides the median.
  options.reference_area = sightings[1].area_px;
  EXPECT_DOUBLE_EQ(blob_poses(sightings, options)[1].position.z(), 1.5);
}

TEST(VisionBlobPose, PositionIsTheCentroidAtTheNominalScale) {
  const std::vector<BlobSighting> sightings = {{4, {320.5, 100.25}, 1000.0, 0.3}};
  const auto mm = blob_poses(sightings, {});  // default 1 px = 1 mm
  ASSERT_EQ(mm.size(), 1u);
  EXPECT_EQ(mm[0].frame, 4u);
  EXPECT_DOUBLE_EQ(mm[0].position.x(), 0.3205);
  EXPECT_DOUBLE_EQ(mm[0].position.y(), 0.10025);
  EXPECT_DOUBLE_EQ(mm[0].position.z(), 1.0);  // its own area is the reference
  EXPECT_DOUBLE_EQ(mm[0].angle, 0.3);
  BlobPoseOptions options;
  options.metres_per_pixel = 0.002;
  EXPECT_DOUBLE_EQ(blob_poses(sightings, options)[0].position.x(), 0.641);
}

TEST(VisionBlobPose, ReferenceAreaIsTheMedianOfTheFirstSightings) {
  std::vector<BlobSighting> sightings;
  for (const double area : {10.0, 50.0, 30.0, 20.0, 40.0, 1000.0})
    sightings.push_back({0, {}, area, 0});
  EXPECT_DOUBLE_EQ(median_reference_area(sightings, 5), 30.0);
  EXPECT_DOUBLE_EQ(median_reference_area(sightings, 4), 25.0);
  EXPECT_DOUBLE_EQ(median_reference_area(sightings, 100), 35.0);  // all six
  EXPECT_THROW(median_reference_area({}, 5), std::invalid_argument);
  EXPECT_THROW(median_reference_area(sightings, 0), std::invalid_argument);
  // Default: the first five, so the outlier at the sixth does not move the depth scale.
  const auto poses = blob_poses(sightings, {});
  EXPECT_DOUBLE_EQ(poses[2].position.z(), 1.0);
  EXPECT_DOUBLE_EQ(poses[5].position.z(), std::sqrt(30.0 / 1000.0));
}

TEST(VisionBlobPose, RejectsBadScalesAndEmptyBlobs) {
  const std::vector<BlobSighting> sightings = {{0, {1.0, 1.0}, 100.0, 0.0}};
  BlobPoseOptions options;
  options.metres_per_pixel = 0.0;
  EXPECT_THROW(blob_poses(sightings, options), std::invalid_argument);
  options = {};
  options.reference_area = -1.0;
  EXPECT_THROW(blob_poses(sightings, options), std::invalid_argument);
  EXPECT_THROW(blob_poses(std::vector<BlobSighting>{{0, {1.0, 1.0}, 0.0, 0.0}}, {}),
               std::invalid_argument);
  EXPECT_TRUE(blob_poses({}, {}).empty());
}

}  // namespace
}  // namespace opf::vision
