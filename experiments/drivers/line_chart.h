#pragma once
// A minimal line chart written as PNG with OpenCV: the experiments' figures (error and trace over
// frames per estimator, in the manner of the paper's Fig. 3) without a plotting dependency.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace opf {

struct ChartSeries {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;  ///< non-finite values leave a gap
  std::uint8_t r = 0, g = 0, b = 0;
};

struct LineChart {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<ChartSeries> series;
  bool log_y = false;  ///< for quantities that grow exponentially (trace of Q~)
  int width = 900;
  int height = 420;
};

/// Renders the chart and writes it as PNG. Throws std::runtime_error naming the path when the
/// file cannot be written, std::invalid_argument for a series whose x and y differ in length.
void write_line_chart(const std::filesystem::path& path, const LineChart& chart);

}  // namespace opf
