#pragma once
// The frames of a real video: a video file OpenCV can decode (cv::VideoCapture), or a folder of
// images read in name order (PNG, JPEG, BMP, TIFF, PPM/PGM), with the video's frame rate when it
// has one, and each frame's timestamp.

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

  /// Decodes the next frame into `bgr` (CV_8UC3); false at the end, or at a frame of a video the
  /// decoder fails on (see missing_at_end()). Throws InputError naming the image when one of a
  /// folder cannot be read or its size differs from the first one's.
  bool read(cv::Mat& bgr);
  /// Moves past the next frame without converting it; false where read() would be.
  bool skip();
  /// Once read() or skip() has returned false: how many frames the container states beyond the
  /// last one decoded (a truncated or damaged file, where decoding stopped; a frame or two is the
  /// usual inexactness of the count; a video that dropped frames as it was recorded may count
  /// them without holding them).
  std::size_t missing_at_end() const { return missing_at_end_; }
  /// The container's timestamp of the frame read last, s (a video's presentation time, which for
  /// evenly spaced frames is frame / fps); nullopt for an image folder or when the video has none.
  std::optional<double> timestamp() const { return timestamp_; }

 private:
  std::filesystem::path path_;
  cv::VideoCapture video_;
  std::vector<std::filesystem::path> images_;  ///< empty for a video
  std::optional<double> fps_;
  std::optional<std::size_t> frame_count_;
  std::size_t next_ = 0;
  cv::Size size_;
  std::size_t missing_at_end_ = 0;
  std::optional<double> timestamp_;

  /// Grabs the next frame of the video and reads its timestamp; false at the end.
  bool grab_next();
};

}  // namespace opf::vision
