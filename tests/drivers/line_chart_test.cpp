#include "drivers/line_chart.h"

#include "drivers/chart_layout.h"
#include "drivers/png_resolution.h"

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace opf {
namespace {

std::filesystem::path temporary_png() {
  return std::filesystem::temp_directory_path() /
         ("opf_line_chart_" + std::to_string(::getpid()) + ".png");
}

cv::Mat draw(const LineChart& chart) {
  const auto path = temporary_png();
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

TEST(LineChart, WritesA2xPngAt200DpiWithTheSeriesInTheirColours) {
  const auto path = temporary_png();
  LineChart chart;
  chart.title = "error";
  ChartSeries red{"opf", {0, 1, 2, 3}, {0.0, 0.1, 0.2, 0.1}, 220, 30, 30};
  ChartSeries blue{"pf", {0, 1, 2, 3}, {0.3, 0.3, std::nan(""), 0.3}, 30, 30, 220};
  chart.series = {red, blue};
  write_line_chart(path, chart);
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
  const cv::Mat image = cv::imread(path.string());
  std::filesystem::remove(path);
  ASSERT_FALSE(image.empty());
  // The default 900 x 420 layout at twice the pixels, stating 200 dpi: 9 x 4.2 inches.
  EXPECT_EQ(image.cols, 1800);
  EXPECT_EQ(image.rows, 840);
  ASSERT_TRUE(png_resolution(bytes).has_value());
  EXPECT_NEAR(*png_resolution(bytes), kPngDotsPerInch, 0.01);
  // Both series' colours appear in the picture (BGR order), lines 4 px wide at 2x.
  EXPECT_GT(pixels_of(image, {30, 30, 220}), 400);
  EXPECT_GT(pixels_of(image, {220, 30, 30}), 400);
  chart.png_scale = 1;
  EXPECT_EQ(draw(chart).cols, 900);
}

TEST(LineChart, MismatchedSeriesAndUnwritablePathAreErrors) {
  LineChart chart;
  chart.series = {ChartSeries{"bad", {0, 1}, {0}, 0, 0, 0}};
  EXPECT_THROW(write_line_chart("/tmp/unused.png", chart), std::invalid_argument);
  chart.series.clear();
  EXPECT_THROW(write_line_chart("/nonexistent-dir/figure.png", chart), std::runtime_error);
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
  // Beyond the legend's samples (two short strokes of about 80 x 8 px each at 2x).
  EXPECT_GT(pixels_of(image, {220, 60, 30}), 1600);
  EXPECT_GT(pixels_of(image, {0, 140, 240}), 1200);
}

TEST(LineChart, MarkersShowASeriesHiddenUnderAnother) {
  // Two series of one width on the same values: the second covers the first's line, and only
  // the first's markers (drawn after every line, half a spacing from the second's) show it.
  LineChart chart;
  std::vector<double> x, y;
  for (int i = 0; i < 120; ++i) x.push_back(i), y.push_back(0.5);
  ChartSeries under{"cvkf", x, y, 30, 160, 60};
  ChartSeries over{"imm", x, y, 140, 60, 200};
  chart.series = {under, over};
  const int without = pixels_of(draw(chart), {60, 160, 30});  // the legend's swatch only
  chart.series[0].marker = Marker::kTriangleUp;
  chart.series[1].marker = Marker::kTriangleDown;
  chart.series[1].marker_phase = 0.5;
  const cv::Mat image = draw(chart);
  EXPECT_GT(pixels_of(image, {60, 160, 30}), without + 12 * 60);  // 12 triangles, 22 px across
  EXPECT_GT(pixels_of(image, {200, 60, 140}), 12 * 60);
}

TEST(LineChart, ValuesAboveTheClipAreMarkedAtTheTopEdge) {
  LineChart chart;
  chart.series = {ChartSeries{"pf", {0, 1, 2, 3}, {0.1, 0.6, 0.7, 0.1}, 30, 60, 220}};
  chart.clip = ChartClip{0.25, "clipped at 0.25 m"};
  const cv::Mat image = draw(chart);
  const ChartLayout l = layout_chart(chart);
  // The triangle in the series' colour just under the plot's top edge, above x = 1.
  const int top = static_cast<int>(std::lround(2.0 * l.plot_top));
  const int x = static_cast<int>(std::lround(2.0 * l.px(1.0)));
  int coloured = 0;
  for (int r = top + 2; r < top + 16; ++r)
    for (int c = x - 4; c <= x + 4; ++c)
      coloured += image.at<cv::Vec3b>(r, c) == cv::Vec3b(220, 60, 30);
  EXPECT_GT(coloured, 30);
}

TEST(LineChart, BandsAreShadedAndReferencesDrawn) {
  LineChart chart;
  chart.series = {ChartSeries{"opf", {0, 10}, {0.0, 1.0}, 220, 30, 30}};
  chart.bands = {{2.0, 4.0}};
  chart.band_label = "hidden";
  chart.references = {{0.5, "alert"}};
  const cv::Mat image = draw(chart);
  const ChartLayout l = layout_chart(chart);
  const double s = chart.png_scale, width = s * l.plot_width, height = s * l.plot_height;
  // The band covers a fifth of the plot's width over its whole height (less the line, the grid
  // and the reference crossing it).
  const int shaded = pixels_of(image, {228, 228, 228});
  EXPECT_GT(shaded, 0.8 * width / 5 * height);
  EXPECT_LT(shaded, 1.1 * width / 5 * height + s * s * ChartLayout::kSwatch * 12);  // and swatch
  // The dashed reference at y = 0.5: dark pixels along its rows.
  const int row = static_cast<int>(std::lround(s * l.py(0.5)));
  const int left = static_cast<int>(std::lround(s * l.plot_left));
  int dark = 0;  // columns with a dark (anti-aliased black) pixel on the reference's rows
  for (int c = left; c < left + static_cast<int>(width); ++c) {
    bool found = false;
    for (int r = row - 2; r <= row + 2; ++r) {
      const cv::Vec3b p = image.at<cv::Vec3b>(r, c);
      found = found || (p[0] < 110 && p[1] < 110 && p[2] < 110);
    }
    dark += found;
  }
  // Dashes 6 widths on, 3.5 off (63%), each dash's round caps one more width: about 75% of the
  // width; a solid line would darken all of it.
  EXPECT_GT(dark, width * 0.6);
  EXPECT_LT(dark, width * 0.85);
}

}  // namespace
}  // namespace opf
