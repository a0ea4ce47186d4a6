#pragma once
// The frames of a real video: a video file OpenCV can decode (cv::VideoCapture), or a folder of
// images read in name order (PNG, JPEG, BMP, TIFF, PPM/PGM), with the video's frame rate when it
// has one.

#include <opencv2/core/mat.hpp>
#include <opencv2/videoio.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <vector>

namespace opf::vision {

class FrameSource {
 public:
  /// Opens `path`. Throws InputError naming it when it does not exist, cannot be decoded as a
  /// video, or is a folder without images.
  explicit FrameSource(const std::filesystem::path& path);

  const std::filesystem::path& path() const { return path_; }
  /// Frames per second as the video file states it; nullopt for an image folder or a video
  /// without a usable rate.
  std::optional<double> fps() const { return fps_; }
  /// The number of frames: the images of a folder, or what the video's container states (which
  /// may be off by a frame or two); nullopt when unknown.
  std::optional<std::size_t> frame_count() const { return frame_count_; }
  /// The number of the frame the next read() returns (0 first).
  std::size_t next_index() const { return next_; }

  /// Decodes the next frame into `bgr` (CV_8UC3); false at the end. Throws InputError naming the
  /// image when one of a folder cannot be read or its size differs from the first one's.
  bool read(cv::Mat& bgr);
  /// Moves past the next frame without decoding it where possible; false at the end.
  bool skip();

 private:
  std::filesystem::path path_;
  cv::VideoCapture video_;
  std::vector<std::filesystem::path> images_;  ///< empty for a video
  std::optional<double> fps_;
  std::optional<std::size_t> frame_count_;
  std::size_t next_ = 0;
  cv::Size size_;
};

}  // namespace opf::vision
