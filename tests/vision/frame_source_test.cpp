#include "opf/vision/frame_source.h"

#include "io/scratch_directory.h"
#include "opf/io/input_error.h"
#include "vision/damaged_video.h"

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace opf::vision {
namespace {

namespace fs = std::filesystem;

class VisionFrameSource : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = empty_scratch_directory("opf_frames"); }
  void TearDown() override { fs::remove_all(dir_); }

  /// A 32x24 image of one grey level.
  void write_image(const std::string& name, int level, cv::Size size = {32, 24}) {
    ASSERT_TRUE(
        cv::imwrite((dir_ / name).string(), cv::Mat(size, CV_8UC3, cv::Scalar::all(level))));
  }

  /// The InputError opening (and reading) `path` raises; fails the test when none.
  InputError error_of(const fs::path& path) {
    try {
      FrameSource source(path);
      cv::Mat frame;
      while (source.read(frame)) {
      }
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no InputError for " << path;
    return InputError("", 0, "", "");
  }

  fs::path dir_;
};

TEST_F(VisionFrameSource, ReadsAFolderOfImagesInNameOrder) {
  write_image("frame_10.png", 30);
  write_image("frame_02.png", 20);
  write_image("frame_01.png", 10);
  std::ofstream(dir_ / "notes.txt") << "not an image\n";
  FrameSource source(dir_);
  EXPECT_FALSE(source.fps().has_value());
  ASSERT_TRUE(source.frame_count().has_value());
  EXPECT_EQ(*source.frame_count(), 3u);
  cv::Mat frame;
  for (const int level : {10, 20, 30}) {
    const std::size_t index = source.next_index();
    ASSERT_TRUE(source.read(frame));
    EXPECT_EQ(frame.type(), CV_8UC3);
    EXPECT_EQ(frame.at<cv::Vec3b>(5, 5)[1], level) << "frame " << index;
  }
  EXPECT_FALSE(source.read(frame));
  EXPECT_EQ(source.next_index(), 3u);
}

TEST_F(VisionFrameSource, SkipMovesPastFrames) {
  for (int i = 0; i < 4; ++i)
    write_image(std::string("f").append(std::to_string(i)).append(".png"), 10 * i);
  FrameSource source(dir_);
  ASSERT_TRUE(source.skip());
  ASSERT_TRUE(source.skip());
  cv::Mat frame;
  ASSERT_TRUE(source.read(frame));
  EXPECT_EQ(frame.at<cv::Vec3b>(0, 0)[0], 20);
  EXPECT_TRUE(source.skip());
  EXPECT_FALSE(source.skip());
}

TEST_F(VisionFrameSource, AVideoIsReadFrameByFrameWithItsTimestamps) {
  const fs::path video = dir_ / "clip.avi";
  test::write_mjpeg_video(video, 20, 10.0);
  FrameSource source(video);
  ASSERT_TRUE(source.fps().has_value());
  EXPECT_DOUBLE_EQ(*source.fps(), 10.0);
  ASSERT_TRUE(source.frame_count().has_value());
  EXPECT_EQ(*source.frame_count(), 20u);
  cv::Mat frame;
  for (int k = 0; k < 20; ++k) {
    ASSERT_TRUE(source.read(frame)) << "frame " << k;
    EXPECT_EQ(source.next_index(), static_cast<std::size_t>(k + 1));
    EXPECT_EQ(test::frame_number(frame), k);
    ASSERT_TRUE(source.timestamp().has_value());
    EXPECT_NEAR(*source.timestamp(), k / 10.0, 1e-6);
  }
  EXPECT_FALSE(source.read(frame));
  EXPECT_FALSE(source.timestamp().has_value());
  EXPECT_EQ(source.missing_at_end(), 0u);
}

TEST_F(VisionFrameSource, ReadingStopsAtADamagedFrameAndSaysHowManyFramesAreLeft) {
  const fs::path video = dir_ / "damaged.avi";
  test::write_mjpeg_video(video, 40, 10.0);
  test::wipe_frames(video, 10, 16);  // frames 10-15
  FrameSource source(video);
  cv::Mat frame;
  std::vector<int> read;
  while (source.read(frame)) read.push_back(test::frame_number(frame));
  // Frames 0-9, each the one the source numbers it: none after the damage, whose numbers the
  // decoder's position could not be trusted for.
  ASSERT_EQ(read.size(), 10u);
  for (int k = 0; k < 10; ++k) EXPECT_EQ(read[static_cast<std::size_t>(k)], k);
  EXPECT_EQ(source.next_index(), 10u);
  EXPECT_EQ(source.missing_at_end(), 30u);

  FrameSource skipping(video);
  while (skipping.skip()) {
  }
  EXPECT_EQ(skipping.next_index(), 10u);
  EXPECT_EQ(skipping.missing_at_end(), 30u);
}

TEST_F(VisionFrameSource, AVideoCutShortSaysHowManyFramesItLacks) {
  const fs::path video = dir_ / "cut.avi";
  test::write_mjpeg_video(video, 40, 10.0);
  test::truncate_file(video, 0.5);
  FrameSource source(video);
  ASSERT_EQ(source.frame_count(), 40u);  // the header is intact
  cv::Mat frame;
  std::size_t read = 0;
  while (source.read(frame)) {
    EXPECT_EQ(test::frame_number(frame), static_cast<int>(read));
    ++read;
  }
  EXPECT_GT(read, 10u);
  EXPECT_LT(read, 30u);
  EXPECT_EQ(source.missing_at_end(), 40u - read);
}

TEST_F(VisionFrameSource, ErrorsNameTheFile) {
  const InputError missing = error_of(dir_ / "missing.avi");
  EXPECT_EQ(missing.file(), (dir_ / "missing.avi").string());

  std::ofstream(dir_ / "text.avi") << "this is not a video\n";
  const InputError text = error_of(dir_ / "text.avi");
  EXPECT_EQ(text.file(), (dir_ / "text.avi").string());
  EXPECT_NE(std::string(text.what()).find("video"), std::string::npos) << text.what();

  const fs::path empty = dir_ / "empty";
  fs::create_directories(empty);
  EXPECT_EQ(error_of(empty).file(), empty.string());

  const fs::path mixed = dir_ / "mixed";
  fs::create_directories(mixed);
  ASSERT_TRUE(cv::imwrite((mixed / "a.png").string(), cv::Mat(24, 32, CV_8UC3, cv::Scalar(0))));
  ASSERT_TRUE(cv::imwrite((mixed / "b.png").string(), cv::Mat(20, 32, CV_8UC3, cv::Scalar(0))));
  const InputError size = error_of(mixed);
  EXPECT_EQ(size.file(), (mixed / "b.png").string());
  EXPECT_NE(size.message().find("32x20"), std::string::npos) << size.what();

  const fs::path broken = dir_ / "broken";
  fs::create_directories(broken);
  std::ofstream(broken / "a.png") << "not a png\n";
  EXPECT_EQ(error_of(broken).file(), (broken / "a.png").string());
}

}  // namespace
}  // namespace opf::vision
