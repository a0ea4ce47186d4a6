#include "opf/vision/detection_overlay.h"

#include "vision/synthetic_image.h"

#include <gtest/gtest.h>

namespace opf::vision {
namespace {

TEST(VisionDetectionOverlay, TintsTheObjectAndLeavesTheRestOfTheFrame) {
  cv::Mat frame = test::plain_frame();
  test::draw_rectangle(frame, {300.0, 300.0}, {200.0, 100.0}, 0.0, test::kYellow);
  SegmenterOptions options;
  options.hsv = {{20, 100, 100}, {40, 255, 255}};
  std::vector<ObjectSegmenter> segmenters = {ObjectSegmenter(options), ObjectSegmenter(options)};
  std::vector<std::optional<Blob>> blobs = {segmenters[0].segment(frame, 0), std::nullopt};
  ASSERT_TRUE(blobs[0].has_value());
  const cv::Mat overlay =
      draw_detection_overlay(FrameResult{0, frame, segmenters, blobs}, {"box", "cup"});
  ASSERT_EQ(overlay.size(), frame.size());
  // A pixel of the box away from the drawn marks is tinted; the far corner is untouched.
  EXPECT_NE(overlay.at<cv::Vec3b>(260, 230), frame.at<cv::Vec3b>(260, 230));
  EXPECT_EQ(overlay.at<cv::Vec3b>(470, 630), frame.at<cv::Vec3b>(470, 630));
  // The object not found is listed in the top-left corner.
  EXPECT_GT(cv::norm(overlay(cv::Rect(0, 0, 150, 30)), frame(cv::Rect(0, 0, 150, 30))), 0.0);
  EXPECT_EQ(cv::norm(frame(cv::Rect(0, 0, 150, 30)), test::plain_frame()(cv::Rect(0, 0, 150, 30))),
            0.0);
}

}  // namespace
}  // namespace opf::vision
