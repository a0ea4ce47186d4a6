#pragma once
// Where everything of a LineChart goes, in layout px (the SVG's; the PNG's times png_scale): the
// axes' ranges and ticks, the plot's rectangle, the legend's entries, which points carry markers
// and clip marks, and the order the series are drawn in. The PNG and the SVG writers both draw
// from it, so the two files show the same chart.

#include "drivers/line_chart.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace opf {

/// Font sizes in OpenCV's Hershey scale (FONT_HERSHEY_SIMPLEX, measured with cv::getTextSize);
/// the SVG's font-size in px is kSvgFontPx times them.
inline constexpr double kTitleFont = 0.6, kLabelFont = 0.5, kTickFont = 0.45, kLegendFont = 0.5;
inline constexpr double kSvgFontPx = 30.0;

/// Width in layout px of `text` in FONT_HERSHEY_SIMPLEX at `font` (tildes, see line_chart.h, take
/// no room).
double text_width(const std::string& text, double font);

/// One axis in plotted values (log10 of the data on a log axis): its ends and its ticks.
struct AxisRange {
  double low = 0.0;
  double high = 1.0;
  std::vector<double> ticks;
};

/// Tick positions at 1, 2 or 5 times a power of ten covering [low, high], about `count` of them.
std::vector<double> nice_ticks(double low, double high, int count);

/// The value a chart plots for a y: log10 on a log axis (non-finite for a gap or y <= 0 there).
double plotted_y(const LineChart& chart, double y);

/// The y axis: every finite value (those above the clip counted at the clip) and every reference
/// line with a margin of 5% of the range beyond it, so that a threshold never lies on the border.
/// A log axis spans whole decades; a linear one starts at zero (or below) and ends on a tick; a
/// map's spans its values with its margin.
AxisRange y_range(const LineChart& chart);

/// A map's axes (LineChart::map) reach this share of their range beyond the data.
inline constexpr double kMapMargin = 0.05;

/// The x axis: from the smallest to the largest finite x (a map's with its margin), ticks at nice
/// steps.
AxisRange x_range(const LineChart& chart);

/// A tick's text: enough decimals to tell ticks `step` apart; powers of ten on a log axis.
std::string tick_text(double value, double step, bool log);

/// The points of `series` that carry a marker: every k-th point with k such that about `count`
/// show, the first `marker_phase` of the way into the spacing; gaps carry none.
std::vector<std::size_t> marker_points(const ChartSeries& series, int count = 12);

/// The points above `limit`, marked at the top edge: the first of each stretch above it, then
/// every k-th as for the markers.
std::vector<std::size_t> clipped_points(const ChartSeries& series, double limit, int count = 12);

/// On/off lengths of a style's dash pattern for a line `width` wide, in the unit of `width`;
/// empty for solid.
std::vector<double> dash_pattern(LineStyle style, double width);

/// A marker's outline around its centre, in layout px, for a marker `size` px across: the
/// polygon of a square, diamond or triangle; empty for a circle, a cross and none.
std::vector<std::array<double, 2>> marker_polygon(Marker marker, double size);

/// The order the series are drawn in: wider first, in legend order among equal widths.
std::vector<std::size_t> draw_order(const LineChart& chart);

/// An entry of the legend, top to bottom: the series, the bands, the references, the clip.
struct LegendEntry {
  enum class Kind { kSeries, kBand, kReference, kClip };
  Kind kind = Kind::kSeries;
  std::string text;
  std::vector<std::size_t> series;  ///< kSeries: the series it shows, its own first
};
std::vector<LegendEntry> legend_entries(const LineChart& chart);

struct ChartLayout {
  double width = 0.0, height = 0.0;
  double plot_left = 0.0, plot_top = 0.0, plot_width = 0.0, plot_height = 0.0;
  AxisRange x, y;
  double legend_left = 0.0;  ///< the swatches' left edge
  double legend_top = 0.0;   ///< the first entry's text baseline
  static constexpr double kRow = 21.0, kSwatch = 40.0, kMarkerSize = 11.0;

  double px(double x_value) const;
  double py(double plotted) const;  ///< of a plotted value (plotted_y)
};

/// Throws std::invalid_argument for a series whose x and y differ in length.
ChartLayout layout_chart(const LineChart& chart);

/// Where a series' marks go, in pixels, for both writers: its markers (marker_points that are
/// plotted and not clipped) and, when the chart clips, its clip marks on the clip line.
struct SeriesMarks {
  std::vector<std::array<double, 2>> markers;
  std::vector<std::array<double, 2>> clips;
};
SeriesMarks series_marks(const LineChart& chart, const ChartSeries& series,
                         const ChartLayout& layout);

}  // namespace opf
