#pragma once
// Motion-JPEG videos for the vision tests, written with OpenCV's FFmpeg writer and then damaged
// on disk: each frame is one JPEG image in the file, so a frame's bytes can be wiped (the decoder
// fails on that frame and goes on with the next) or the file cut short.

#include "vision/synthetic_image.h"

#include <opencv2/videoio.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace opf::vision::test {

/// Frame k's red channel, at every pixel off the rectangle: the frame's number, read back by
/// frame_number.
inline int frame_number_level(int k) {
  return 4 * k + 20;
}

/// The number of a frame of write_mjpeg_video, from its background's red level (JPEG moves it by
/// a level or two).
inline int frame_number(const cv::Mat& bgr) {
  return static_cast<int>(std::lround((bgr.at<cv::Vec3b>(5, 5)[2] - 20) / 4.0));
}

/// `frames` frames of 320x240 at `fps`: a yellow rectangle 60x30 px at (100 + 4k, 120) on a
/// background whose red channel is frame_number_level(k). Fails the test when it cannot be written.
inline void write_mjpeg_video(const std::filesystem::path& path, int frames, double fps) {
  cv::VideoWriter writer(path.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                         fps, {320, 240});
  ASSERT_TRUE(writer.isOpened()) << "cannot write " << path;
  for (int k = 0; k < frames; ++k) {
    cv::Mat frame = plain_frame(cv::Scalar(90, 60, frame_number_level(k)), {320, 240});
    draw_rectangle(frame, {100.0 + 4 * k, 120.0}, {60, 30}, 0.0, kYellow);
    writer.write(frame);
  }
}

/// The file's bytes.
inline std::vector<char> file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Zeroes the JPEG data of frames [from, to) of a Motion-JPEG file, in place (the length and the
/// container's index stay): those frames no longer decode.
inline void wipe_frames(const std::filesystem::path& path, std::size_t from, std::size_t to) {
  std::vector<char> bytes = file_bytes(path);
  std::vector<std::size_t> starts;  // JPEG start-of-image markers FF D8 FF
  for (std::size_t i = 0; i + 2 < bytes.size(); ++i)
    if (static_cast<unsigned char>(bytes[i]) == 0xff &&
        static_cast<unsigned char>(bytes[i + 1]) == 0xd8 &&
        static_cast<unsigned char>(bytes[i + 2]) == 0xff)
      starts.push_back(i);
  ASSERT_GT(starts.size(), to) << path << ": fewer JPEG frames than expected";
  // Up to the next frame's marker, less the container's chunk header before it (8 bytes).
  for (std::size_t i = starts[from]; i + 8 < starts[to]; ++i) bytes[i] = 0;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), bytes.size());
}

/// Cuts the file to `fraction` of its length.
inline void truncate_file(const std::filesystem::path& path, double fraction) {
  std::vector<char> bytes = file_bytes(path);
  bytes.resize(static_cast<std::size_t>(fraction * static_cast<double>(bytes.size())));
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), bytes.size());
}

}  // namespace opf::vision::test
