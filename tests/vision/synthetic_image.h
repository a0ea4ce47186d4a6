#pragma once
// Synthetic frames for the vision tests: filled rotated rectangles drawn with sub-pixel precision
// on plain or noisy backgrounds.

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <array>
#include <cmath>
#include <cstdint>

namespace opf::vision::test {

inline const cv::Scalar kYellow(0, 230, 230);     // BGR; OpenCV HSV (30, 255, 230)
inline const cv::Scalar kBackground(90, 60, 40);  // dark blue-grey; HSV hue 105
inline const cv::Scalar kSkin(140, 170, 220);     // BGR; HSV hue 12, saturation 93

inline cv::Mat plain_frame(const cv::Scalar& colour = kBackground, cv::Size size = {640, 480}) {
  return cv::Mat(size, CV_8UC3, colour);
}

/// Static texture: grey levels uniform in [80, 160) per pixel and channel, fixed by `seed`.
inline cv::Mat noise_frame(std::uint64_t seed, cv::Size size = {640, 480}) {
  cv::Mat frame(size, CV_8UC3);
  cv::RNG rng(seed);
  rng.fill(frame, cv::RNG::UNIFORM, 80, 160);
  return frame;
}

/// A filled rectangle of `size` (width along the angle) centred at `centre`, turned by
/// `angle_deg` from +u towards +v, with corners at 1/256 px precision. OpenCV fills the outline
/// too: with an integer centre, an axis-aligned W x H rectangle covers (W + 1) x (H + 1) pixels,
/// a turned one about as many, and the pixels' centroid is the centre (within 0.05 px).
inline void draw_rectangle(cv::Mat& frame, cv::Point2d centre, cv::Size2d size, double angle_deg,
                           const cv::Scalar& colour) {
  constexpr int kShift = 8;
  const cv::RotatedRect rect(
      centre, cv::Size2f(static_cast<float>(size.width), static_cast<float>(size.height)),
      static_cast<float>(angle_deg));
  std::array<cv::Point2f, 4> corners;
  rect.points(corners.data());
  std::array<cv::Point, 4> fixed;
  for (std::size_t i = 0; i < 4; ++i)
    fixed[i] = cv::Point(static_cast<int>(std::lround(corners[i].x * (1 << kShift))),
                         static_cast<int>(std::lround(corners[i].y * (1 << kShift))));
  cv::fillConvexPoly(frame, fixed.data(), 4, colour, cv::LINE_8, kShift);
}

}  // namespace opf::vision::test
