#pragma once
// A minimal line chart written as PNG with OpenCV: the experiments' figures (error and trace over
// time per estimator, in the manner of the paper's Fig. 3) without a plotting dependency. The same
// chart is written as SVG by svg_line_chart.h; both draw from chart_layout.h.
//
// Titles and labels are plain text, except that "~" after a character draws a tilde above it
// ("Q~" is Q with a tilde): OpenCV's Hershey fonts have no combining marks.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace opf {

/// How a series' line is drawn; style as well as colour tells series apart, also in grey print.
enum class LineStyle { kSolid, kDashed, kDotted, kDashDot };

/// A shape drawn on a series every few points (about a dozen per series) and in its legend entry:
/// a series hidden under another's line still shows by its markers.
enum class Marker { kNone, kCircle, kSquare, kDiamond, kTriangleUp, kTriangleDown, kCross };

struct ChartSeries {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;  ///< non-finite values leave a gap
  std::uint8_t r = 0, g = 0, b = 0;
  LineStyle style = LineStyle::kSolid;
  /// px. Wider series are drawn first, so a narrower one on the same values shows inside them.
  int width = 2;
  Marker marker = Marker::kNone;
  /// Where the markers start, as a fraction in [0, 1) of their spacing: series on the same values
  /// with different phases put their markers between each other's.
  double marker_phase = 0.0;
  /// False for a series named by another's legend entry (see coinciding_series.h).
  bool in_legend = true;
  /// Series (indices into LineChart::series) on exactly these values: this entry of the legend
  /// names them too and shows their markers beside its own.
  std::vector<std::size_t> coinciding = {};
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

/// An upper limit of the y axis: values above it are drawn at the top edge, marked there by an
/// upward triangle in the series' colour, and the legend says so with `label` ("clipped at 0.25
/// m"). For a quantity a few estimators lose by orders of magnitude, so the others stay readable.
struct ChartClip {
  double above = 0.0;
  std::string label;
};

struct LineChart {
  std::string title;
  std::string x_label;
  std::string y_label;
  /// In the order of the legend; drawn wider first, in this order among equal widths.
  std::vector<ChartSeries> series;
  bool log_y = false;  ///< for quantities that grow exponentially (trace of Q~)
  /// A map (a top view): both axes reach kMapMargin of their range beyond the data on either
  /// side, zero or not, so that no path ends on the frame.
  bool map = false;
  /// The layout's size: the SVG's in px, the PNG's times `png_scale`.
  int width = 900;
  int height = 420;
  std::vector<ChartBand> bands;
  std::string band_label;  ///< the legend's entry for the bands ("hidden")
  std::vector<ChartReference> references;
  std::optional<ChartClip> clip;
  /// PNG pixels per layout px (lines, fonts and margins alike): 2 gives 1800 x 840 px, printed
  /// at kPngDotsPerInch 9 x 4.2 inches.
  int png_scale = 2;
};

/// The resolution a chart's PNG states (its pHYs chunk).
inline constexpr double kPngDotsPerInch = 200.0;

/// Renders the chart and writes it as PNG of width x height times png_scale pixels, stating
/// kPngDotsPerInch. Throws std::runtime_error naming the path when the file cannot be written,
/// std::invalid_argument for a series whose x and y differ in length.
void write_line_chart(const std::filesystem::path& path, const LineChart& chart);

}  // namespace opf
