#include "drivers/line_chart.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace opf {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
const cv::Scalar kBlack(0, 0, 0);

/// Text where "~" after a character draws a tilde above that character.
void draw_text(cv::Mat& image, const std::string& text, cv::Point origin, double scale,
               int thickness = 1) {
  std::string plain;
  std::vector<std::size_t> marked;  // indices in `plain` of characters with a tilde
  for (const char c : text) {
    if (c == '~' && !plain.empty())
      marked.push_back(plain.size() - 1);
    else
      plain += c;
  }
  cv::putText(image, plain, origin, kFont, scale, kBlack, thickness, cv::LINE_AA);
  int baseline = 0;
  for (const std::size_t i : marked) {
    const int before =
        cv::getTextSize(plain.substr(0, i), kFont, scale, thickness, &baseline).width;
    const cv::Size glyph = cv::getTextSize(plain.substr(i, 1), kFont, scale, thickness, &baseline);
    // A sine wave over the glyph's width, a few pixels above its top.
    std::vector<cv::Point> wave;
    const double top = origin.y - glyph.height - 4.0 * scale;
    for (int k = 0; k <= 8; ++k) {
      const double u = k / 8.0;
      wave.emplace_back(int(std::lround(origin.x + before + 1 + u * (glyph.width - 2))),
                        int(std::lround(top - 2.5 * scale * std::sin(2.0 * M_PI * u))));
    }
    cv::polylines(image, wave, false, kBlack, 1, cv::LINE_AA);
  }
}

/// On/off lengths (px) of a style's pattern; empty for solid.
std::vector<double> dash_pattern(LineStyle style, int width) {
  const double w = std::max(1, width);
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

/// A polyline drawn in the style's pattern, the pattern running on across its vertices.
void draw_styled(cv::Mat& image, const std::vector<cv::Point2d>& points, const cv::Scalar& colour,
                 int width, LineStyle style) {
  const std::vector<double> pattern = dash_pattern(style, width);
  if (pattern.empty()) {
    for (std::size_t i = 1; i < points.size(); ++i)
      cv::line(image, points[i - 1], points[i], colour, width, cv::LINE_AA);
    return;
  }
  std::size_t phase = 0;
  double left = pattern[0];  // of the current on or off stretch
  for (std::size_t i = 1; i < points.size(); ++i) {
    cv::Point2d a = points[i - 1];
    const cv::Point2d b = points[i];
    double length = std::hypot(b.x - a.x, b.y - a.y);
    while (length > 0.0) {
      const double step = std::min(left, length);
      const cv::Point2d c = a + (b - a) * (step / length);
      if (phase % 2 == 0) cv::line(image, a, c, colour, width, cv::LINE_AA);
      a = c;
      length -= step;
      left -= step;
      if (left <= 0.0) {
        phase = (phase + 1) % pattern.size();
        left = pattern[phase];
      }
    }
  }
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

void write_line_chart(const std::filesystem::path& path, const LineChart& chart) {
  // The legend's column: its swatch (40 px) and its longest label, at least 175 px.
  int legend_width = 0, legend_baseline = 0;
  for (const ChartSeries& series : chart.series)
    legend_width = std::max(legend_width,
                            cv::getTextSize(series.label, kFont, 0.45, 1, &legend_baseline).width);
  const int left = 80, right = std::max(175, 12 + 40 + legend_width + 10), top = 58, bottom = 55;
  cv::Mat image(chart.height, chart.width, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Rect plot(left, top, chart.width - left - right, chart.height - top - bottom);

  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  const auto value = [&](double y) { return chart.log_y ? std::log10(y) : y; };
  const auto include_y = [&](double v) {
    if (!std::isfinite(v)) return;
    y0 = std::min(y0, v);
    y1 = std::max(y1, v);
  };
  for (const ChartSeries& s : chart.series) {
    if (s.x.size() != s.y.size())
      throw std::invalid_argument("line chart '" + chart.title + "': series '" + s.label +
                                  "' has x and y of different lengths");
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(value(s.y[i])) || !std::isfinite(s.x[i])) continue;
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      include_y(value(s.y[i]));
    }
  }
  for (const ChartReference& r : chart.references) include_y(value(r.y));
  if (!std::isfinite(x0)) x0 = 0.0, x1 = 1.0;
  if (!(x1 > x0)) x1 = x0 + 1.0;
  if (!std::isfinite(y0)) y0 = 0.0, y1 = 1.0;
  std::vector<double> y_ticks;  // in the plotted value (log10 for a log axis)
  if (chart.log_y) {
    // Whole decades, so every tick is a round number; 2 and 5 within them when there are few.
    y0 = std::floor(y0);
    y1 = std::max(std::ceil(y1), y0 + 1.0);
    for (double d = y0; d <= y1 + 1e-9; d += 1.0) {
      y_ticks.push_back(d);
      if (y1 - y0 <= 2.0 && d < y1)
        for (const double m : {2.0, 5.0}) y_ticks.push_back(d + std::log10(m));
    }
  } else {
    y0 = std::min(y0, 0.0);
    if (!(y1 > y0)) y1 = y0 + 1.0;
    y_ticks = nice_ticks(y0, y1, 5);
    const double step = y_ticks.size() > 1 ? y_ticks[1] - y_ticks[0] : 1.0;
    if (y_ticks.back() < y1) y_ticks.push_back(y_ticks.back() + step);
    y1 = y_ticks.back();
  }
  const std::vector<double> x_ticks = nice_ticks(x0, x1, 6);
  const auto px = [&](double x) { return plot.x + (x - x0) / (x1 - x0) * plot.width; };
  const auto py = [&](double v) {
    return plot.y + plot.height - (v - y0) / (y1 - y0) * plot.height;
  };

  const cv::Scalar band_grey(228, 228, 228), grid(210, 210, 210);
  for (const ChartBand& band : chart.bands) {
    const double a = std::clamp(px(band.from), double(plot.x), double(plot.x + plot.width));
    const double b = std::clamp(px(band.to), double(plot.x), double(plot.x + plot.width));
    if (b > a)
      cv::rectangle(image, cv::Point2d(a, plot.y), cv::Point2d(b, plot.y + plot.height), band_grey,
                    cv::FILLED);
  }
  const double y_step = y_ticks.size() > 1 ? y_ticks[1] - y_ticks[0] : 1.0;
  for (const double v : y_ticks) {
    const int y = int(std::lround(py(v)));
    cv::line(image, {plot.x, y}, {plot.x + plot.width, y}, grid, 1);
    const std::string text =
        chart.log_y ? decimal_text(std::pow(10.0, v), std::pow(10.0, v)) : decimal_text(v, y_step);
    int baseline = 0;
    const int w = cv::getTextSize(text, kFont, 0.4, 1, &baseline).width;
    cv::putText(image, text, {plot.x - 6 - w, y + 4}, kFont, 0.4, kBlack, 1, cv::LINE_AA);
  }
  const double x_step = x_ticks.size() > 1 ? x_ticks[1] - x_ticks[0] : 1.0;
  for (const double xv : x_ticks) {
    const int x = int(std::lround(px(xv)));
    cv::line(image, {x, plot.y}, {x, plot.y + plot.height}, grid, 1);
    const std::string text = decimal_text(xv, x_step);
    int baseline = 0;
    const int w = cv::getTextSize(text, kFont, 0.4, 1, &baseline).width;
    cv::putText(image, text, {x - w / 2, plot.y + plot.height + 18}, kFont, 0.4, kBlack, 1,
                cv::LINE_AA);
  }
  for (const ChartReference& r : chart.references) {
    const double y = py(value(r.y));
    draw_styled(image, {cv::Point2d(plot.x, y), cv::Point2d(plot.x + plot.width, y)}, kBlack, 1,
                LineStyle::kDashed);
  }

  // Wider series first, so that narrower ones on the same values stay visible inside them.
  std::vector<std::size_t> order(chart.series.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return chart.series[a].width > chart.series[b].width;
  });
  // Drawn on a copy of which only the plot goes back: the lines are clipped to the plot.
  cv::Mat canvas = image.clone();
  for (const std::size_t k : order) {
    const ChartSeries& s = chart.series[k];
    const cv::Scalar colour(s.b, s.g, s.r);
    std::vector<cv::Point2d> run;
    const auto flush = [&] {
      if (run.size() > 1) draw_styled(canvas, run, colour, s.width, s.style);
      run.clear();
    };
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const double v = value(s.y[i]);
      if (!std::isfinite(v) || !std::isfinite(s.x[i])) {
        flush();
        continue;
      }
      run.emplace_back(px(s.x[i]), py(v));
    }
    flush();
  }
  canvas(plot).copyTo(image(plot));
  cv::rectangle(image, plot, kBlack, 1);

  draw_text(image, chart.title, {left, 26}, 0.6);
  draw_text(image, chart.y_label, {8, plot.y - 10}, 0.45);
  int baseline = 0;
  const int x_label_width = cv::getTextSize(chart.x_label, kFont, 0.45, 1, &baseline).width;
  draw_text(image, chart.x_label, {plot.x + (plot.width - x_label_width) / 2, chart.height - 12},
            0.45);

  const int lx = plot.x + plot.width + 12;
  int legend_y = plot.y + 15;
  for (const ChartSeries& s : chart.series) {
    const cv::Scalar colour(s.b, s.g, s.r);
    draw_styled(image, {cv::Point2d(lx, legend_y - 4), cv::Point2d(lx + 34, legend_y - 4)}, colour,
                s.width, s.style);
    draw_text(image, s.label, {lx + 40, legend_y}, 0.45);
    legend_y += 20;
  }
  if (!chart.bands.empty() && !chart.band_label.empty()) {
    cv::rectangle(image, {lx, legend_y - 10}, {lx + 34, legend_y + 1}, band_grey, cv::FILLED);
    draw_text(image, chart.band_label, {lx + 40, legend_y}, 0.45);
    legend_y += 20;
  }
  for (const ChartReference& r : chart.references) {
    draw_styled(image, {cv::Point2d(lx, legend_y - 4), cv::Point2d(lx + 34, legend_y - 4)}, kBlack,
                1, LineStyle::kDashed);
    draw_text(image, r.label, {lx + 40, legend_y}, 0.45);
    legend_y += 20;
  }
  if (!cv::imwrite(path.string(), image))
    throw std::runtime_error("cannot write the figure " + path.string());
}

}  // namespace opf
