#include "opf/vision/frame_source.h"

#include "opf/io/input_error.h"
#include "opf/io/input_file.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>
#include <string_view>
#include <system_error>

namespace opf::vision {

namespace {

constexpr std::array<std::string_view, 9> kImageExtensions = {
    ".png", ".jpg", ".jpeg", ".bmp", ".tif", ".tiff", ".ppm", ".pgm", ".pnm"};

bool is_image(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return std::find(kImageExtensions.begin(), kImageExtensions.end(), extension) !=
         kImageExtensions.end();
}

std::string size_text(const cv::Size& size) {
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}

}  // namespace

FrameSource::FrameSource(const std::filesystem::path& path) : path_(path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    for (const auto& entry : std::filesystem::directory_iterator(path, error))
      if (entry.is_regular_file() && is_image(entry.path())) images_.push_back(entry.path());
    if (error) throw InputError(path.string(), 0, "", "cannot list the folder: " + error.message());
    if (images_.empty())
      throw InputError(path.string(), 0, "",
                       "expected a video file or a folder of images (png, jpg, bmp, tif, ppm), "
                       "got a folder without images");
    std::sort(images_.begin(), images_.end(), [](const auto& a, const auto& b) {
      return a.filename().string() < b.filename().string();
    });
    frame_count_ = images_.size();
    return;
  }
  // Missing files and unreadable ones get the toolkit's usual messages.
  open_input_file(path, "video").close();
  // FFmpeg, OpenCV's file decoder on Debian: letting OpenCV probe every backend would also try
  // GStreamer pipelines and cameras, which print their own errors and leak on the way.
  if (!video_.open(path.string(), cv::CAP_FFMPEG) || !video_.isOpened())
    throw InputError(path.string(), 0, "",
                     "cannot be read as a video: FFmpeg (OpenCV's decoder) cannot decode it");
  const double fps = video_.get(cv::CAP_PROP_FPS);
  if (std::isfinite(fps) && fps > 0.0 && fps < 10000.0) fps_ = fps;
  const double count = video_.get(cv::CAP_PROP_FRAME_COUNT);
  if (std::isfinite(count) && count >= 1.0) frame_count_ = static_cast<std::size_t>(count);
}

bool FrameSource::read(cv::Mat& bgr) {
  if (images_.empty()) {
    if (!grab_next()) return false;
    if (!video_.retrieve(bgr) || bgr.empty())
      throw InputError(path_.string(), 0, "",
                       "frame " + std::to_string(next_) + " was decoded but cannot be read");
  } else {
    if (next_ >= images_.size()) return false;
    const std::filesystem::path& image = images_[next_];
    bgr = cv::imread(image.string(), cv::IMREAD_COLOR);
    if (bgr.empty()) throw InputError(image.string(), 0, "", "cannot be read as an image");
  }
  if (bgr.type() == CV_8UC1) cv::cvtColor(bgr, bgr, cv::COLOR_GRAY2BGR);
  if (bgr.type() != CV_8UC3)
    throw InputError(images_.empty() ? path_.string() : images_[next_].string(), 0, "",
                     "expected 8-bit colour or grey frames");
  if (size_.empty()) size_ = bgr.size();
  if (bgr.size() != size_)
    throw InputError(images_.empty() ? path_.string() : images_[next_].string(), 0, "",
                     "frame " + std::to_string(next_) + " is " + size_text(bgr.size()) +
                         " but the first frame was " + size_text(size_));
  ++next_;
  return true;
}

bool FrameSource::skip() {
  if (images_.empty() ? !grab_next() : next_ >= images_.size()) return false;
  ++next_;
  return true;
}

bool FrameSource::grab_next() {
  if (!video_.grab()) {
    // The end, or a frame the decoder fails on. After a damaged frame the decoder may go on, but
    // how many frames it passed over cannot be known for certain (the container's positions and
    // timestamps follow the frames decoded, not the ones lost), and frames numbered wrongly would
    // put wrong times in the log. So reading stops, and what the container states beyond is
    // reported.
    missing_at_end_ = frame_count_ && *frame_count_ > next_ ? *frame_count_ - next_ : 0;
    timestamp_.reset();
    return false;
  }
  const double milliseconds = video_.get(cv::CAP_PROP_POS_MSEC);
  // To the microsecond: the container's time base in seconds, without the float noise of its
  // conversion to milliseconds in the log's times (2.066677, not 2.0666770000000003).
  timestamp_ = std::isfinite(milliseconds) && milliseconds >= 0.0
                   ? std::optional<double>(std::round(milliseconds * 1000.0) / 1e6)
                   : std::nullopt;
  return true;
}

}  // namespace opf::vision
