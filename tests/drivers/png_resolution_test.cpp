#include "drivers/png_resolution.h"

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

std::vector<std::uint8_t> small_png() {
  std::vector<std::uint8_t> png;
  cv::imencode(".png", cv::Mat(4, 6, CV_8UC3, cv::Scalar(10, 20, 30)), png);
  return png;
}

TEST(PngResolution, StatesTheDotsPerInchAndDecodesUnchanged) {
  const std::vector<std::uint8_t> plain = small_png();
  EXPECT_FALSE(png_resolution(plain).has_value());  // OpenCV writes no pHYs
  const std::vector<std::uint8_t> stated = with_png_resolution(plain, 200.0);
  ASSERT_TRUE(png_resolution(stated).has_value());
  // 200 dpi is 7874 pixels per metre, stored whole: 199.9996 dpi back.
  EXPECT_NEAR(*png_resolution(stated), 200.0, 0.001);
  EXPECT_EQ(stated.size(), plain.size() + 21);  // one chunk: length, type, 9 bytes, CRC
  const cv::Mat image = cv::imdecode(stated, cv::IMREAD_COLOR);
  ASSERT_EQ(image.cols, 6);
  EXPECT_EQ(image.at<cv::Vec3b>(2, 3), cv::Vec3b(10, 20, 30));
}

TEST(PngResolution, ReplacesAStatedResolutionAndChecksTheCrc) {
  const std::vector<std::uint8_t> once = with_png_resolution(small_png(), 300.0);
  const std::vector<std::uint8_t> twice = with_png_resolution(once, 150.0);
  EXPECT_EQ(twice.size(), once.size());
  EXPECT_NEAR(*png_resolution(twice), 150.0, 0.02);  // 5906 px/m: 150.012 dpi
  // The pHYs chunk right after the 8-byte signature and the 25-byte header chunk, with the
  // CRC-32 of its type and data (as zlib computes it for these bytes).
  const std::vector<std::uint8_t> phys(twice.begin() + 33, twice.begin() + 33 + 21);
  // 150 dpi: 5906 (0x1712) pixels per metre.
  const std::vector<std::uint8_t> expected = {0,    0,    0,    9,    'p',  'H',  'Y',
                                              's',  0x00, 0x00, 0x17, 0x12, 0x00, 0x00,
                                              0x17, 0x12, 0x01, 0x67, 0x9f, 0xd2, 0x52};
  EXPECT_EQ(phys, expected);
}

TEST(PngResolution, RefusesBytesThatAreNotAPng) {
  const std::vector<std::uint8_t> text = {'n', 'o', 't', ' ', 'a', ' ', 'p', 'n', 'g'};
  EXPECT_THROW(with_png_resolution(text, 200.0), std::invalid_argument);
  EXPECT_FALSE(png_resolution(text).has_value());
}

}  // namespace
}  // namespace opf
