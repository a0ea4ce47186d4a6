#include "drivers/chart_layout.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace opf {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Points between markers (and clip marks) for about `count` of them on `points` points.
std::size_t marker_spacing(std::size_t points, int count) {
  const double per = static_cast<double>(points) / std::max(1, count);
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(per)));
}

bool above(double y, double limit) {
  return std::isfinite(y) && y > limit;
}

bool any_clipped(const LineChart& chart) {
  if (!chart.clip) return false;
  for (const ChartSeries& s : chart.series)
    if (std::any_of(s.y.begin(), s.y.end(), [&](double y) { return above(y, chart.clip->above); }))
      return true;
  return false;
}

/// The smallest and largest plotted value of the series, those above the clip at the clip.
std::pair<double, double> data_extent(const LineChart& chart) {
  double low = kInfinity, high = -kInfinity;
  const double clip = chart.clip ? plotted_y(chart, chart.clip->above) : kInfinity;
  for (const ChartSeries& s : chart.series)
    for (const double y : s.y) {
      const double v = plotted_y(chart, y);
      if (!std::isfinite(v)) continue;
      low = std::min(low, std::min(v, clip));
      high = std::max(high, std::min(v, clip));
    }
  return {low, high};
}

/// Whole decades, with 2 and 5 within them when there are few.
AxisRange log_axis(double low, double high) {
  AxisRange axis;
  axis.low = std::floor(low);
  axis.high = std::max(std::ceil(high), axis.low + 1.0);
  for (double d = axis.low; d <= axis.high + 1e-9; d += 1.0) {
    axis.ticks.push_back(d);
    if (axis.high - axis.low <= 2.0 && d < axis.high)
      for (const double m : {2.0, 5.0}) axis.ticks.push_back(d + std::log10(m));
  }
  return axis;
}

/// From zero (or below) to a tick above `high` by 3% of the range at least: a curve that levels
/// off at its largest value then runs below the border, not on it (where it would look clipped).
AxisRange linear_axis(double low, double high) {
  AxisRange axis;
  axis.low = std::min(low, 0.0);
  axis.high = high > axis.low ? high : axis.low + 1.0;
  axis.ticks = nice_ticks(axis.low, axis.high, 5);
  const double step = axis.ticks.size() > 1 ? axis.ticks[1] - axis.ticks[0] : 1.0;
  const double top = axis.high + 0.03 * (axis.high - axis.low);
  while (axis.ticks.back() < top) axis.ticks.push_back(axis.ticks.back() + step);
  axis.high = axis.ticks.back();
  return axis;
}

std::string decimal_text(double v, double step) {
  // Enough decimals to tell ticks `step` apart, no exponent unless the numbers are tiny or huge.
  char buffer[32];
  const double magnitude = std::max(std::abs(v), std::abs(step));
  if (magnitude != 0.0 && (magnitude < 1e-4 || magnitude >= 1e6)) {
    std::snprintf(buffer, sizeof buffer, "%.0e", v);
  } else {
    const int decimals = std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, std::abs(v) < step * 1e-9 ? 0.0 : v);
  }
  return buffer;
}

}  // namespace

double text_width(const std::string& text, double font) {
  std::string plain;
  for (const char c : text)
    if (c != '~' || plain.empty()) plain += c;
  int baseline = 0;
  return cv::getTextSize(plain, cv::FONT_HERSHEY_SIMPLEX, font, 1, &baseline).width;
}

std::vector<double> nice_ticks(double low, double high, int count) {
  if (!(high > low) || count < 1) return {low};
  const double raw = (high - low) / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= raw) {
      step = m * power;
      break;
    }
  std::vector<double> ticks;
  for (double k = std::ceil(low / step - 1e-9); k * step <= high + step * 1e-9; k += 1.0)
    ticks.push_back(k * step);
  return ticks;
}

double plotted_y(const LineChart& chart, double y) {
  return chart.log_y ? std::log10(y) : y;
}

/// [low, high] widened by kMapMargin of its width on either side.
AxisRange map_axis(double low, double high, int ticks) {
  if (!std::isfinite(low)) low = 0.0, high = 1.0;
  const double margin = kMapMargin * (high > low ? high - low : 1.0);
  return {low - margin, high + margin, nice_ticks(low - margin, high + margin, ticks)};
}

AxisRange y_range(const LineChart& chart) {
  auto [low, high] = data_extent(chart);
  if (chart.map) return map_axis(low, high, 5);
  std::vector<double> references;
  for (const ChartReference& r : chart.references)
    if (const double v = plotted_y(chart, r.y); std::isfinite(v)) references.push_back(v);
  for (const double v : references) low = std::min(low, v), high = std::max(high, v);
  if (!std::isfinite(low)) low = 0.0, high = 1.0;
  // The margin around each reference line: 5% of the range, of one decade or unit if flat.
  const double margin = 0.05 * (high > low ? high - low : 1.0);
  for (const double v : references)
    low = std::min(low, v - margin), high = std::max(high, v + margin);
  if (chart.log_y) return log_axis(low, high);
  if (chart.clip && any_clipped(chart) && chart.clip->above > std::max(low, 0.0)) {
    AxisRange axis;  // the top edge at the clip, where the clipped values are marked
    axis.low = std::min(low, 0.0);
    axis.high = std::max(high, chart.clip->above);
    axis.ticks = nice_ticks(axis.low, axis.high, 5);
    return axis;
  }
  return linear_axis(low, high);
}

AxisRange x_range(const LineChart& chart) {
  double low = kInfinity, high = -kInfinity;
  for (const ChartSeries& s : chart.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(plotted_y(chart, s.y[i])) || !std::isfinite(s.x[i])) continue;
      low = std::min(low, s.x[i]);
      high = std::max(high, s.x[i]);
    }
  if (chart.map) return map_axis(low, high, 6);
  if (!std::isfinite(low)) low = 0.0, high = 1.0;
  if (!(high > low)) high = low + 1.0;
  return {low, high, nice_ticks(low, high, 6)};
}

std::string tick_text(double value, double step, bool log) {
  return log ? decimal_text(std::pow(10.0, value), std::pow(10.0, value))
             : decimal_text(value, step);
}

std::vector<std::size_t> marker_points(const ChartSeries& series, int count) {
  if (series.marker == Marker::kNone) return {};
  const std::size_t n = std::min(series.x.size(), series.y.size());
  const std::size_t k = marker_spacing(n, count);
  const double phase = std::clamp(series.marker_phase, 0.0, 1.0 - 1e-9);
  std::vector<std::size_t> points;
  for (auto i = static_cast<std::size_t>(std::floor(phase * static_cast<double>(k))); i < n; i += k)
    if (std::isfinite(series.x[i]) && std::isfinite(series.y[i])) points.push_back(i);
  return points;
}

std::vector<std::size_t> clipped_points(const ChartSeries& series, double limit, int count) {
  const std::size_t n = std::min(series.x.size(), series.y.size());
  const std::size_t k = marker_spacing(n, count);
  std::vector<std::size_t> points;
  for (std::size_t i = 0; i < n; ++i) {
    if (!above(series.y[i], limit) || !std::isfinite(series.x[i])) continue;
    const bool starts = i == 0 || !above(series.y[i - 1], limit);
    if (starts || points.empty() || i - points.back() >= k) points.push_back(i);
  }
  return points;
}

std::vector<double> dash_pattern(LineStyle style, double width) {
  const double w = std::max(1.0, width);
  switch (style) {
    case LineStyle::kDashed:
      return {6.0 * w, 3.5 * w};
    case LineStyle::kDotted:
      return {0.8 * w, 2.2 * w};
    case LineStyle::kDashDot:
      return {6.0 * w, 2.5 * w, 0.8 * w, 2.5 * w};
    case LineStyle::kSolid:
      break;
  }
  return {};
}

std::vector<std::array<double, 2>> marker_polygon(Marker marker, double size) {
  const double h = 0.5 * size;
  switch (marker) {
    case Marker::kSquare:
      return {{-0.8 * h, -0.8 * h}, {0.8 * h, -0.8 * h}, {0.8 * h, 0.8 * h}, {-0.8 * h, 0.8 * h}};
    case Marker::kDiamond:
      return {{0.0, -h}, {h, 0.0}, {0.0, h}, {-h, 0.0}};
    case Marker::kTriangleUp:
      return {{0.0, -h}, {h, 0.75 * h}, {-h, 0.75 * h}};
    case Marker::kTriangleDown:
      return {{0.0, h}, {h, -0.75 * h}, {-h, -0.75 * h}};
    case Marker::kCircle:
    case Marker::kCross:
    case Marker::kNone:
      break;
  }
  return {};
}

std::vector<std::size_t> draw_order(const LineChart& chart) {
  std::vector<std::size_t> order(chart.series.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return chart.series[a].width > chart.series[b].width;
  });
  return order;
}

std::vector<LegendEntry> legend_entries(const LineChart& chart) {
  using Kind = LegendEntry::Kind;
  std::vector<LegendEntry> entries;
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    const ChartSeries& s = chart.series[i];
    if (!s.in_legend) continue;
    LegendEntry entry{Kind::kSeries, s.label, {i}};
    for (const std::size_t j : s.coinciding)
      if (j < chart.series.size() && j != i) entry.series.push_back(j);
    entries.push_back(std::move(entry));
  }
  if (!chart.bands.empty() && !chart.band_label.empty())
    entries.push_back({Kind::kBand, chart.band_label, {}});
  for (const ChartReference& r : chart.references)
    entries.push_back({Kind::kReference, r.label, {}});
  if (any_clipped(chart) && !chart.clip->label.empty())
    entries.push_back({Kind::kClip, chart.clip->label, {}});
  return entries;
}

double ChartLayout::px(double x_value) const {
  return plot_left + (x_value - x.low) / (x.high - x.low) * plot_width;
}

double ChartLayout::py(double plotted) const {
  return plot_top + plot_height - (plotted - y.low) / (y.high - y.low) * plot_height;
}

ChartLayout layout_chart(const LineChart& chart) {
  for (const ChartSeries& s : chart.series)
    if (s.x.size() != s.y.size())
      throw std::invalid_argument("line chart '" + chart.title + "': series '" + s.label +
                                  "' has x and y of different lengths");
  ChartLayout layout;
  layout.width = chart.width;
  layout.height = chart.height;
  layout.x = x_range(chart);
  layout.y = y_range(chart);
  // Left: room for the widest y tick; right: the legend's column, its swatch and longest text.
  const double y_step = layout.y.ticks.size() > 1 ? layout.y.ticks[1] - layout.y.ticks[0] : 1.0;
  double tick_width = 0.0, legend_width = 0.0;
  for (const double v : layout.y.ticks)
    tick_width = std::max(tick_width, text_width(tick_text(v, y_step, chart.log_y), kTickFont));
  for (const LegendEntry& e : legend_entries(chart))
    legend_width = std::max(legend_width, text_width(e.text, kLegendFont));
  const double right = std::max(175.0, 12.0 + ChartLayout::kSwatch + 6.0 + legend_width + 10.0);
  layout.plot_left = std::max(56.0, tick_width + 16.0);
  layout.plot_top = 60.0;
  layout.plot_width = std::max(1.0, layout.width - layout.plot_left - right);
  layout.plot_height = std::max(1.0, layout.height - layout.plot_top - 58.0);
  layout.legend_left = layout.plot_left + layout.plot_width + 12.0;
  layout.legend_top = layout.plot_top + 15.0;
  return layout;
}

SeriesMarks series_marks(const LineChart& chart, const ChartSeries& series,
                         const ChartLayout& layout) {
  SeriesMarks marks;
  for (const std::size_t i : marker_points(series)) {
    const double v = plotted_y(chart, series.y[i]);
    if (std::isfinite(v) && !(chart.clip && series.y[i] > chart.clip->above))
      marks.markers.push_back({layout.px(series.x[i]), layout.py(v)});
  }
  if (!chart.clip) return marks;
  const double clip_y = layout.py(plotted_y(chart, chart.clip->above));
  for (const std::size_t i : clipped_points(series, chart.clip->above))
    marks.clips.push_back({layout.px(series.x[i]), clip_y});
  return marks;
}

}  // namespace opf
