#include "opf/vision/object_segmenter.h"

#include "opf/vision/blob_pose.h"
#include "vision/synthetic_image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace opf::vision {
namespace {

using test::draw_rectangle;
using test::kSkin;
using test::kYellow;
using test::plain_frame;

constexpr double kDeg = std::numbers::pi / 180.0;

SegmenterOptions yellow() {
  SegmenterOptions options;
  options.method = SegmentationMethod::kHsv;
  options.hsv = {{20, 100, 100}, {40, 255, 255}};
  return options;
}

TEST(VisionObjectSegmenter, FindsARotatedYellowRectangle) {
  cv::Mat frame = plain_frame();
  draw_rectangle(frame, {300.0, 200.0}, {200.0, 80.0}, 30.0, kYellow);
  ObjectSegmenter segmenter(yellow());
  const auto blob = segmenter.segment(frame, 0);
  ASSERT_TRUE(blob.has_value());
  EXPECT_NEAR(blob->centroid_px.x, 300.0, 0.5);
  EXPECT_NEAR(blob->centroid_px.y, 200.0, 0.5);
  EXPECT_NEAR(blob->area_px, 201.0 * 81.0, 0.01 * 201.0 * 81.0);  // the outline is filled too
  EXPECT_NEAR(principal_axis_angle(blob->moments), 30.0 * kDeg, 0.01);
  EXPECT_EQ(blob->components, 1);
  EXPECT_EQ(cv::countNonZero(segmenter.object_mask()), static_cast<int>(blob->area_px));
}

TEST(VisionObjectSegmenter, TakesTheLargestComponentNotADistantSmallerOne) {
  cv::Mat frame = plain_frame();
  draw_rectangle(frame, {200.0, 300.0}, {120.0, 60.0}, 0.0, kYellow);
  draw_rectangle(frame, {520.0, 80.0}, {60.0, 60.0}, 0.0, kYellow);  // 3600 px, 180+ px away
  ObjectSegmenter segmenter(yellow());
  const auto blob = segmenter.segment(frame, 0);
  ASSERT_TRUE(blob.has_value());
  EXPECT_EQ(blob->components, 1);
  EXPECT_NEAR(blob->centroid_px.x, 200.0, 0.5);
  EXPECT_NEAR(blob->centroid_px.y, 300.0, 0.5);
  EXPECT_NEAR(blob->area_px, 121.0 * 61.0, 10.0);
}

TEST(VisionObjectSegmenter, MergesTheTwoHalvesOfAnObjectCutByAHand) {
  cv::Mat frame = plain_frame();
  draw_rectangle(frame, {320.0, 240.0}, {240.0, 100.0}, 0.0, kYellow);
  // A skin-coloured arm across the middle (x = 308..332): two halves of 108 x 101 px (x = 200..307
  // and 333..440), 25 px apart.
  draw_rectangle(frame, {320.0, 200.0}, {24.0, 300.0}, 0.0, kSkin);
  SegmenterOptions options = yellow();
  options.fragment_fraction = 0.5;
  options.fragment_distance_px = 30.0;
  ObjectSegmenter merging(options);
  const auto whole = merging.segment(frame, 0);
  ASSERT_TRUE(whole.has_value());
  EXPECT_EQ(whole->components, 2);
  EXPECT_NEAR(whole->centroid_px.x, 320.0, 0.5);  // symmetric cut: the centre is kept
  EXPECT_NEAR(whole->centroid_px.y, 240.0, 0.5);
  EXPECT_NEAR(whole->area_px, 2 * 108.0 * 101.0, 20.0);
  EXPECT_EQ(whole->bounds, cv::Rect(200, 190, 241, 101));

  // A gap wider than the fragment distance leaves one half: its centroid is 66.5 px off centre.
  options.fragment_distance_px = 20.0;
  ObjectSegmenter strict(options);
  const auto half = strict.segment(frame, 0);
  ASSERT_TRUE(half.has_value());
  EXPECT_EQ(half->components, 1);
  EXPECT_NEAR(std::abs(half->centroid_px.x - 320.0), 66.5, 0.1);
  EXPECT_NEAR(half->area_px, 108.0 * 101.0, 10.0);
}

TEST(VisionObjectSegmenter, FragmentsBelowTheAreaFractionAreNotMerged) {
  cv::Mat frame = plain_frame();
  draw_rectangle(frame, {300.0, 240.0}, {100.0, 100.0}, 0.0, kYellow);  // 10000 px
  draw_rectangle(frame, {370.0, 240.0}, {20.0, 20.0}, 0.0, kYellow);    // 400 px, 10 px away
  SegmenterOptions options = yellow();
  options.fragment_fraction = 0.03;
  options.fragment_distance_px = 15.0;
  EXPECT_EQ(ObjectSegmenter(options).segment(frame, 0)->components, 2);
  options.fragment_fraction = 0.1;  // the small square is 4% of the large one
  const auto blob = ObjectSegmenter(options).segment(frame, 0);
  ASSERT_TRUE(blob.has_value());
  EXPECT_EQ(blob->components, 1);
  EXPECT_NEAR(blob->centroid_px.x, 300.0, 0.5);
}

TEST(VisionObjectSegmenter, AFrameWithoutTheObjectIsUnobserved) {
  ObjectSegmenter segmenter(yellow());
  cv::Mat with = plain_frame();
  draw_rectangle(with, {300.0, 200.0}, {100.0, 50.0}, 0.0, kYellow);
  ASSERT_TRUE(segmenter.segment(with, 0).has_value());
  EXPECT_FALSE(segmenter.segment(plain_frame(), 1).has_value());
  EXPECT_EQ(cv::countNonZero(segmenter.object_mask()), 0);
  // Skin is not yellow: a hand alone is no detection either.
  cv::Mat hand = plain_frame();
  draw_rectangle(hand, {300.0, 200.0}, {100.0, 50.0}, 0.0, kSkin);
  EXPECT_FALSE(segmenter.segment(hand, 2).has_value());
}

TEST(VisionObjectSegmenter, ABlobBelowTheMinimumAreaIsUnobserved) {
  cv::Mat frame = plain_frame();
  draw_rectangle(frame, {300.0, 200.0}, {20.0, 20.0}, 0.0, kYellow);  // 400 px
  SegmenterOptions options = yellow();
  options.min_area_px = 450.0;
  EXPECT_FALSE(ObjectSegmenter(options).segment(frame, 0).has_value());
  options.min_area_px = 350.0;
  EXPECT_TRUE(ObjectSegmenter(options).segment(frame, 0).has_value());
}

TEST(VisionObjectSegmenter, OpeningRemovesSpecksClosingFillsHoles) {
  cv::Mat frame = plain_frame();
  draw_rectangle(frame, {300.0, 200.0}, {100.0, 100.0}, 0.0, kYellow);
  // 101 x 101 px with a hole of 7 x 7 px, and a speck of 3 x 3 px 4 px to the right of it.
  draw_rectangle(frame, {300.0, 200.0}, {6.0, 6.0}, 0.0, test::kBackground);
  draw_rectangle(frame, {356.0, 200.0}, {2.0, 2.0}, 0.0, kYellow);
  SegmenterOptions options = yellow();
  options.open_px = 0;
  options.close_px = 0;
  options.fragment_distance_px = 5.0;
  options.fragment_fraction = 0.0;
  const auto raw = ObjectSegmenter(options).segment(frame, 0);
  ASSERT_TRUE(raw.has_value());
  EXPECT_EQ(raw->components, 2);
  EXPECT_EQ(raw->area_px, 101.0 * 101.0 - 49.0 + 9.0);
  options.open_px = 5;
  options.close_px = 9;
  const auto cleaned = ObjectSegmenter(options).segment(frame, 0);
  ASSERT_TRUE(cleaned.has_value());
  EXPECT_EQ(cleaned->components, 1);
  EXPECT_NEAR(cleaned->area_px, 101.0 * 101.0, 12.0);  // the opening rounds the corners a little
  EXPECT_NEAR(cleaned->centroid_px.x, 300.0, 0.5);
}

TEST(VisionObjectSegmenter, HueRangeWrapsAroundRed) {
  cv::Mat frame = plain_frame(cv::Scalar(128, 128, 128));  // grey: saturation 0
  draw_rectangle(frame, {200.0, 200.0}, {80.0, 80.0}, 0.0, cv::Scalar(0, 0, 255));  // hue 0
  SegmenterOptions options;
  options.hsv = {{170, 100, 100}, {10, 255, 255}};
  const auto red = ObjectSegmenter(options).segment(frame, 0);
  ASSERT_TRUE(red.has_value());
  EXPECT_NEAR(red->centroid_px.x, 200.0, 0.5);
  options.hsv = {{10, 100, 100}, {170, 255, 255}};  // everything but red
  EXPECT_FALSE(ObjectSegmenter(options).segment(frame, 0).has_value());
}

TEST(VisionObjectSegmenter, DarkAndLightThresholdsOnGreyLevel) {
  cv::Mat frame = plain_frame(cv::Scalar(128, 128, 128));
  draw_rectangle(frame, {150.0, 150.0}, {60.0, 60.0}, 0.0, cv::Scalar(40, 40, 40));
  draw_rectangle(frame, {450.0, 300.0}, {60.0, 60.0}, 0.0, cv::Scalar(220, 220, 220));
  SegmenterOptions options;
  options.method = SegmentationMethod::kDark;
  options.grey_threshold = 40;  // inclusive
  const auto dark = ObjectSegmenter(options).segment(frame, 0);
  ASSERT_TRUE(dark.has_value());
  EXPECT_NEAR(dark->centroid_px.x, 150.0, 0.5);
  EXPECT_NEAR(dark->centroid_px.y, 150.0, 0.5);
  options.grey_threshold = 39;
  EXPECT_FALSE(ObjectSegmenter(options).segment(frame, 0).has_value());

  options.method = SegmentationMethod::kLight;
  options.grey_threshold = 220;  // inclusive
  const auto light = ObjectSegmenter(options).segment(frame, 0);
  ASSERT_TRUE(light.has_value());
  EXPECT_NEAR(light->centroid_px.x, 450.0, 0.5);
  EXPECT_NEAR(light->centroid_px.y, 300.0, 0.5);
  options.grey_threshold = 221;
  EXPECT_FALSE(ObjectSegmenter(options).segment(frame, 0).has_value());
}

TEST(VisionObjectSegmenter, PixelsOutsideTheRegionOfInterestAreIgnored) {
  cv::Mat frame = plain_frame();
  draw_rectangle(frame, {150.0, 150.0}, {40.0, 40.0}, 0.0, kYellow);
  draw_rectangle(frame, {450.0, 300.0}, {150.0, 100.0}, 0.0, kYellow);  // larger, outside
  SegmenterOptions options = yellow();
  options.roi = cv::Rect(50, 50, 250, 200);
  const auto blob = ObjectSegmenter(options).segment(frame, 0);
  ASSERT_TRUE(blob.has_value());
  EXPECT_NEAR(blob->centroid_px.x, 150.0, 0.5);
  EXPECT_NEAR(blob->centroid_px.y, 150.0, 0.5);
  options.roi = cv::Rect(700, 500, 10, 10);  // outside the 640x480 frame
  EXPECT_THROW(ObjectSegmenter(options).segment(frame, 0), std::invalid_argument);
}

/// Background subtraction on a textured scene: a red square (the object, from `start`) and a
/// larger red square (another mover) appear at frame 20 and cross the scene; the object is
/// followed from start_frame (30) on. A slow learning rate keeps the squares out of the model.
TEST(VisionObjectSegmenter, BackgroundSubtractionFollowsTheMoverFromItsStartPoint) {
  SegmenterOptions options;
  options.method = SegmentationMethod::kBackground;
  options.background.start_frame = 30;
  options.background.start = {102.0, 198.0};
  options.background.gate_px = 30.0;
  options.background.shadows = true;
  options.background.learning_rate = 0.005;
  options.min_area_px = 200.0;
  ObjectSegmenter segmenter(options);
  const cv::Mat scene = test::noise_frame(7);
  const auto object_at = [](std::size_t k) {
    return cv::Point2d(100.0 + 4.0 * (static_cast<double>(k) - 30.0), 200.0);
  };
  const auto other_at = [](std::size_t k) {
    return cv::Point2d(500.0 - 3.0 * (static_cast<double>(k) - 30.0), 300.0);
  };
  for (std::size_t k = 0; k < 90; ++k) {
    cv::Mat frame = scene.clone();
    const bool hidden = k == 60;  // the object is missing from one frame
    if (k >= 20 && !hidden) draw_rectangle(frame, object_at(k), {30.0, 30.0}, 0.0, {0, 0, 255});
    if (k >= 20) draw_rectangle(frame, other_at(k), {50.0, 50.0}, 0.0, {0, 0, 255});
    const auto blob = segmenter.segment(frame, k);
    if (k < 30 || hidden) {
      EXPECT_FALSE(blob.has_value()) << "frame " << k;
      continue;
    }
    ASSERT_TRUE(blob.has_value()) << "frame " << k;
    EXPECT_NEAR(blob->centroid_px.x, object_at(k).x, 0.5) << "frame " << k;
    EXPECT_NEAR(blob->centroid_px.y, object_at(k).y, 0.5) << "frame " << k;
    EXPECT_NEAR(blob->area_px, 31.0 * 31.0, 8.0) << "frame " << k;
  }
}

TEST(VisionObjectSegmenter, BackgroundSubtractionFindsNothingOutsideTheGate) {
  SegmenterOptions options;
  options.method = SegmentationMethod::kBackground;
  options.background.start = {100.0, 100.0};
  options.background.gate_px = 50.0;
  ObjectSegmenter segmenter(options);
  const cv::Mat scene = test::noise_frame(3);
  for (std::size_t k = 0; k < 10; ++k) segmenter.segment(scene, k);
  cv::Mat frame = scene.clone();
  draw_rectangle(frame, {160.0, 100.0}, {30.0, 30.0}, 0.0, {0, 0, 255});  // 60 px from start
  EXPECT_FALSE(segmenter.segment(frame, 10).has_value());
  EXPECT_GT(cv::countNonZero(segmenter.candidate_mask()), 800);  // seen, but not taken
}

TEST(VisionObjectSegmenter, RejectsBadOptionsAndChangingFrameSizes) {
  const auto rejects = [](auto change) {
    SegmenterOptions options;
    change(options);
    EXPECT_THROW(ObjectSegmenter{options}, std::invalid_argument);
  };
  rejects([](SegmenterOptions& o) { o.hsv.low[0] = 180; });
  rejects([](SegmenterOptions& o) { o.hsv.high[2] = 256; });
  rejects([](SegmenterOptions& o) {
    o.hsv.low[1] = 200;
    o.hsv.high[1] = 100;
  });
  rejects([](SegmenterOptions& o) { o.grey_threshold = 300; });
  rejects([](SegmenterOptions& o) { o.fragment_fraction = 1.5; });
  rejects([](SegmenterOptions& o) { o.open_px = -1; });
  rejects([](SegmenterOptions& o) { o.background.gate_px = 0.0; });
  rejects([](SegmenterOptions& o) { o.background.learning_rate = 2.0; });
  ObjectSegmenter segmenter(yellow());
  segmenter.segment(plain_frame(), 0);
  EXPECT_THROW(segmenter.segment(plain_frame(test::kBackground, {320, 240}), 1),
               std::invalid_argument);
  EXPECT_THROW(segmenter.segment(cv::Mat(480, 640, CV_8UC1, cv::Scalar(0)), 2),
               std::invalid_argument);
}

}  // namespace
}  // namespace opf::vision
