#include "drivers/line_chart.h"

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>

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

}  // namespace
}  // namespace opf
