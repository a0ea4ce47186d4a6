#include "drivers/line_chart.h"

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <vector>

namespace opf {
namespace {

TEST(LineChart, WritesAPngWithTheSeriesDrawnInTheirColours) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("opf_line_chart_" + std::to_string(::getpid()) + ".png");
  LineChart chart;
  chart.title = "error";
  ChartSeries red{"opf", {0, 1, 2, 3}, {0.0, 0.1, 0.2, 0.1}, 220, 30, 30};
  ChartSeries blue{"pf", {0, 1, 2, 3}, {0.3, 0.3, std::nan(""), 0.3}, 30, 30, 220};
  chart.series = {red, blue};
  write_line_chart(path, chart);
  const cv::Mat image = cv::imread(path.string());
  std::filesystem::remove(path);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, chart.width);
  EXPECT_EQ(image.rows, chart.height);
  // Both series' colours appear in the picture (BGR order).
  int red_pixels = 0, blue_pixels = 0;
  for (int r = 0; r < image.rows; ++r)
    for (int c = 0; c < image.cols; ++c) {
      const cv::Vec3b p = image.at<cv::Vec3b>(r, c);
      red_pixels += p[2] == 220 && p[1] == 30 && p[0] == 30;
      blue_pixels += p[0] == 220 && p[1] == 30 && p[2] == 30;
    }
  EXPECT_GT(red_pixels, 100);
  EXPECT_GT(blue_pixels, 100);
}

TEST(LineChart, MismatchedSeriesAndUnwritablePathAreErrors) {
  LineChart chart;
  chart.series = {ChartSeries{"bad", {0, 1}, {0}, 0, 0, 0}};
  EXPECT_THROW(write_line_chart("/tmp/unused.png", chart), std::invalid_argument);
  chart.series.clear();
  EXPECT_THROW(write_line_chart("/nonexistent-dir/figure.png", chart), std::runtime_error);
}

TEST(LineChart, TicksAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_EQ(nice_ticks(0.0, 10.97, 6), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(nice_ticks(0.0, 0.047, 5), (std::vector<double>{0, 0.01, 0.02, 0.03, 0.04}));
  const std::vector<double> ticks = nice_ticks(-3.0, 7.5, 4);  // step 5 (2.625 raw)
  EXPECT_EQ(ticks, (std::vector<double>{0, 5}));
}

cv::Mat draw(const LineChart& chart) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("opf_line_chart_" + std::to_string(::getpid()) + ".png");
  write_line_chart(path, chart);
  cv::Mat image = cv::imread(path.string());
  std::filesystem::remove(path);
  return image;
}

int pixels_of(const cv::Mat& image, cv::Vec3b bgr) {
  int count = 0;
  for (int r = 0; r < image.rows; ++r)
    for (int c = 0; c < image.cols; ++c) count += image.at<cv::Vec3b>(r, c) == bgr;
  return count;
}

TEST(LineChart, SeriesOnTheSameValuesAreAllVisible) {
  // Two baselines with the same constant value: the wider dashed one is drawn first, the narrower
  // dotted one inside it, so both colours show along the whole line.
  LineChart chart;
  ChartSeries wide{"pf", {0, 10}, {0.5, 0.5}, 30, 60, 220};
  const ChartSeries range{"range", {0, 10}, {0.0, 1.0}, 0, 0, 0};  // puts 0.5 mid-plot
  wide.style = LineStyle::kDashed;
  wide.width = 4;
  ChartSeries narrow{"oapf", {0, 10}, {0.5, 0.5}, 240, 140, 0};
  narrow.style = LineStyle::kDotted;
  narrow.width = 2;
  chart.series = {narrow, wide, range};  // narrow first: the drawing order must not rely on it
  const cv::Mat image = draw(chart);
  // Beyond the legend's samples (two short strokes of about 34 px each).
  EXPECT_GT(pixels_of(image, {220, 60, 30}), 400);
  EXPECT_GT(pixels_of(image, {0, 140, 240}), 300);
}

TEST(LineChart, BandsAreShadedAndReferencesDrawn) {
  LineChart chart;
  chart.series = {ChartSeries{"opf", {0, 10}, {0.0, 1.0}, 220, 30, 30}};
  chart.bands = {{2.0, 4.0}};
  chart.band_label = "hidden";
  chart.references = {{0.5, "alert"}};
  const cv::Mat image = draw(chart);
  // The band covers a fifth of the plot's width over its whole height (less the line, the grid
  // and the reference crossing it): 645 x 307 px plot.
  const int shaded = pixels_of(image, {228, 228, 228});
  EXPECT_GT(shaded, 0.8 * 645 / 5 * 307);
  EXPECT_LT(shaded, 1.1 * 645 / 5 * 307 + 34 * 11);  // and the legend's swatch
  // The dashed reference at y = 0.5: black pixels along the plot's middle row.
  const int row = 58 + 307 / 2;
  int dark = 0;  // columns with a dark (anti-aliased black) pixel on the reference's rows
  for (int c = 80; c < 80 + 645; ++c) {
    bool found = false;
    for (int r = row - 1; r <= row + 1; ++r) {
      const cv::Vec3b p = image.at<cv::Vec3b>(r, c);
      found = found || (p[0] < 110 && p[1] < 110 && p[2] < 110);
    }
    dark += found;
  }
  // Dashes 6 px on, 3.5 off: about 63% of the width.
  EXPECT_GT(dark, 645 / 2);
  EXPECT_LT(dark, 645 * 3 / 4);
}

}  // namespace
}  // namespace opf
