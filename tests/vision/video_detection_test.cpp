#include "opf/vision/video_detection.h"

#include "opf/io/input_error.h"
#include "opf/io/measurement_log.h"
#include "vision/synthetic_image.h"

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

namespace opf::vision {
namespace {

namespace fs = std::filesystem;

/// Frames 0..5: a yellow rectangle moving 10 px per frame to the right from (100, 200), turned by
/// 20 degrees; frame 3 has none.
class VisionVideoDetection : public ::testing::Test {
 protected:
  void SetUp() override {
    // One directory per test: ctest runs the tests of this suite in parallel.
    dir_ = fs::temp_directory_path() /
           ("opf_video_detection_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    for (int k = 0; k < 6; ++k) {
      cv::Mat frame = test::plain_frame(test::kBackground, {320, 240});
      if (k != 3)
        test::draw_rectangle(frame, {100.0 + 10 * k, 120.0}, {60, 30}, 20.0, test::kYellow);
      const std::string name = std::string("f").append(std::to_string(k)).append(".png");
      ASSERT_TRUE(cv::imwrite((dir_ / name).string(), frame));
    }
    ObjectSpec box;
    box.name = "box";
    box.segmentation.hsv = {{20, 100, 100}, {40, 255, 255}};
    spec_.objects.push_back(box);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  SegmentationSpec spec_;
};

TEST_F(VisionVideoDetection, SegmentsTheRangeAndLeavesMissedFramesOut) {
  FrameSource source(dir_);
  std::vector<std::size_t> observed_frames;
  const VideoDetection detection =
      detect_in_video(source, spec_, 1, 4, [&](const FrameResult& result) {
        observed_frames.push_back(result.frame);
        EXPECT_EQ(result.blobs.size(), 1u);
        EXPECT_EQ(result.blobs[0].has_value(), result.frame != 3);
      });
  EXPECT_EQ(observed_frames, (std::vector<std::size_t>{1, 2, 3, 4}));
  EXPECT_EQ(detection.first_frame, 1u);
  EXPECT_EQ(detection.frames, 4u);
  ASSERT_EQ(detection.objects.size(), 1u);
  const ObjectTrack& box = detection.objects[0];
  ASSERT_EQ(box.sightings.size(), 3u);  // frames 1, 2 and 4
  EXPECT_EQ(box.sightings[2].frame, 4u);
  EXPECT_NEAR(box.sightings[2].centroid_px.x, 140.0, 0.5);
  ASSERT_EQ(box.poses.size(), 3u);

  std::ostringstream out;
  write_detection_log(out, detection, 20.0);
  std::istringstream in(out.str());
  const MeasurementLog log = parse_measurement_log(in, "detections.csv");
  ASSERT_EQ(log.frames.size(), 3u);
  EXPECT_EQ(log.frames[0].t, 1.0 / 20.0);
  EXPECT_EQ(log.frames[2].t, 4.0 / 20.0);
  const Detection& last = log.frames[2].detections.at(0);
  EXPECT_EQ(last.object, "box");
  EXPECT_NEAR(last.pose.x(), 0.140, 0.0005);
  EXPECT_NEAR(last.pose.y(), 0.120, 0.0005);
  EXPECT_NEAR(last.pose.z(), 1.0, 0.01);  // same size throughout
  EXPECT_NEAR(last.pose.yaw(), 20.0 * M_PI / 180.0, 0.01);
  EXPECT_NEAR(last.pose.pitch(), 0.0, 1e-9);
  EXPECT_NEAR(last.pose.roll(), 0.0, 1e-9);
  EXPECT_THROW(write_detection_log(out, detection, 0.0), std::invalid_argument);
}

TEST_F(VisionVideoDetection, AFirstFrameBeyondTheEndNamesTheVideo) {
  FrameSource source(dir_);
  try {
    detect_in_video(source, spec_, 6, std::nullopt);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), dir_.string());
  }
}

}  // namespace
}  // namespace opf::vision
