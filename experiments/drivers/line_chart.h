#pragma once
// A minimal line chart written as PNG with OpenCV: the experiments' figures (error and trace over
// time per estimator, in the manner of the paper's Fig. 3) without a plotting dependency.
//
// Titles and labels are plain text, except that "~" after a character draws a tilde above it
// ("Q~" is Q with a tilde): OpenCV's Hershey fonts have no combining marks.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace opf {

/// How a series' line is drawn; style as well as colour tells series apart, also in grey print.
enum class LineStyle { kSolid, kDashed, kDotted, kDashDot };

struct ChartSeries {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;  ///< non-finite values leave a gap
  std::uint8_t r = 0, g = 0, b = 0;
  LineStyle style = LineStyle::kSolid;
  /// px. Wider series are drawn first, so a narrower one on the same values shows inside them.
  int width = 2;
};

/// An interval of x shaded behind the lines (e.g. where the object was hidden).
struct ChartBand {
  double from = 0.0;
  double to = 0.0;
};

/// A horizontal reference line (e.g. a threshold), dashed black, named in the legend.
struct ChartReference {
  double y = 0.0;
  std::string label;
};

struct LineChart {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<ChartSeries> series;
  bool log_y = false;  ///< for quantities that grow exponentially (trace of Q~)
  int width = 900;
  int height = 420;
  std::vector<ChartBand> bands;
  std::string band_label;  ///< the legend's entry for the bands ("hidden")
  std::vector<ChartReference> references;
};

/// Tick positions at 1, 2 or 5 times a power of ten covering [low, high], about `count` of them.
std::vector<double> nice_ticks(double low, double high, int count);

/// Renders the chart and writes it as PNG. Throws std::runtime_error naming the path when the
/// file cannot be written, std::invalid_argument for a series whose x and y differ in length.
void write_line_chart(const std::filesystem::path& path, const LineChart& chart);

}  // namespace opf
