#include "opf/vision/video_detection.h"

#include "io/scratch_directory.h"
#include "opf/io/input_error.h"
#include "opf/io/measurement_log.h"
#include "vision/damaged_video.h"
#include "vision/synthetic_image.h"

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace opf::vision {
namespace {

namespace fs = std::filesystem;

/// Frames 0..5: a yellow rectangle moving 10 px per frame to the right from (100, 200), turned by
/// 20 degrees; frame 3 has none.
class VisionVideoDetection : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = empty_scratch_directory("opf_video_detection");
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

/// A detection of frames 0..n-1 at 10 Hz with one sighting each and the given timestamps.
VideoDetection stamped_detection(const std::vector<double>& stamps) {
  VideoDetection detection;
  detection.frames = stamps.size();
  ObjectTrack track{"box", {}, {}};
  for (std::size_t k = 0; k < stamps.size(); ++k) {
    detection.timestamps.emplace(k, stamps[k]);
    BlobPose pose;
    pose.frame = k;
    track.poses.push_back(pose);
  }
  detection.objects.push_back(track);
  return detection;
}

TEST(VisionVideoTiming, EvenlySpacedFramesKeepFrameOverRate) {
  const VideoDetection even = stamped_detection({0.0, 0.1, 0.2000004, 0.3, 0.4});
  EXPECT_FALSE(uneven_frames(even, 10.0).has_value());
  // Times that start late are still evenly spaced.
  EXPECT_FALSE(uneven_frames(stamped_detection({0.067, 0.167, 0.267, 0.367}), 10.0).has_value());
  std::ostringstream out;
  write_detection_log(out, even, 10.0);
  std::istringstream in(out.str());
  const MeasurementLog log = parse_measurement_log(in, "even.csv");
  ASSERT_EQ(log.frames.size(), 5u);
  EXPECT_EQ(log.frames[2].t, 2.0 / 10.0);  // frame / fps, not the timestamp's last digits
}

TEST(VisionVideoTiming, FramesDroppedWhileRecordingTakeTheirOwnTimestamps) {
  // A 10 Hz container whose recorder dropped frames: the third frame kept is stamped 0.7 s.
  const VideoDetection dropped = stamped_detection({0.0, 0.1, 0.7, 0.8, 1.3});
  const std::optional<UnevenFrames> uneven = uneven_frames(dropped, 10.0);
  ASSERT_TRUE(uneven.has_value());
  EXPECT_EQ(uneven->frame, 2u);
  EXPECT_DOUBLE_EQ(uneven->timestamp, 0.7);
  EXPECT_DOUBLE_EQ(uneven->at_the_rate, 0.2);
  std::ostringstream out;
  write_detection_log(out, dropped, 10.0, true);
  std::istringstream in(out.str());
  std::vector<std::string> times;
  for (std::string line; std::getline(in, line);) times.push_back(line.substr(0, line.find(',')));
  EXPECT_EQ(times, (std::vector<std::string>{"t", "0", "0.1", "0.7", "0.8", "1.3"}));

  // Half a frame off is still even; a frame's worth is not.
  EXPECT_FALSE(uneven_frames(stamped_detection({0.0, 0.1, 0.249}), 10.0).has_value());
  EXPECT_TRUE(uneven_frames(stamped_detection({0.0, 0.1, 0.251}), 10.0).has_value());
}

TEST(VisionVideoTiming, TimestampsOutOfOrderOrMissingSayNothing) {
  // The packet order of a video with B-frames: the timestamps do not increase.
  EXPECT_FALSE(uneven_frames(stamped_detection({0.067, 0.101, 0.067, 0.134}), 30.0).has_value());
  VideoDetection partly = stamped_detection({0.0, 0.5, 1.0});
  partly.timestamps.erase(1);
  EXPECT_FALSE(uneven_frames(partly, 10.0).has_value());
  std::ostringstream out;
  EXPECT_THROW(write_detection_log(out, partly, 10.0, true), std::invalid_argument);
}

TEST(VisionVideoTiming, MissingFramesAreCountedInTime) {
  // Decoding stopped at frame 10 of 40 evenly spaced ones: 30 are missing.
  std::vector<double> even;
  for (int k = 0; k < 10; ++k) even.push_back(k / 10.0);
  VideoDetection cut = stamped_detection(even);
  cut.missing_at_end = 30;
  EXPECT_EQ(frames_missing_at_end(cut, 10.0, false), 30u);
  EXPECT_EQ(frames_missing_at_end(cut, 10.0, true), 30u);
  // Ten frames kept of a 40-frame recording that dropped the rest, the last at 3.9 s: timed by
  // their stamps, they end where the container says, and nothing is missing.
  std::vector<double> kept;
  for (int k = 0; k < 10; ++k) kept.push_back(0.3 + 0.4 * k);
  VideoDetection sparse = stamped_detection(kept);
  sparse.missing_at_end = 30;
  EXPECT_EQ(frames_missing_at_end(sparse, 10.0, true), 0u);
  // Timed at frame / fps (a rate given, or no increasing timestamps), they end at frame 9.
  EXPECT_EQ(frames_missing_at_end(sparse, 10.0, false), 30u);
  sparse.timestamps.clear();
  EXPECT_EQ(frames_missing_at_end(sparse, 10.0, true), 30u);
  cut.missing_at_end = 0;
  EXPECT_EQ(frames_missing_at_end(cut, 10.0, true), 0u);
}

/// The InputError detecting from frame `first` of `path` on raises; fails the test when none.
InputError detection_error(const fs::path& path, const SegmentationSpec& spec, std::size_t first) {
  FrameSource source(path);
  try {
    detect_in_video(source, spec, first, std::nullopt);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for " << path;
  return InputError("", 0, "", "");
}

TEST_F(VisionVideoDetection, AVideoDamagedBeforeTheFirstFrameAskedForSaysWhere) {
  const fs::path video = dir_ / "damaged.avi";
  test::write_mjpeg_video(video, 40, 10.0);
  test::wipe_frames(video, 10, 16);
  const InputError error = detection_error(video, spec_, 20);
  EXPECT_EQ(error.file(), video.string());
  EXPECT_NE(error.message().find("decoding failed at frame 10 of the 40 the video states"),
            std::string::npos)
      << error.what();
}

TEST_F(VisionVideoDetection, AFirstFrameBeyondTheEndNamesTheVideo) {
  EXPECT_EQ(detection_error(dir_, spec_, 6).file(), dir_.string());
}

}  // namespace
}  // namespace opf::vision
