#include "drivers/line_chart.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace opf {
namespace {

std::string tick_text(double v, bool log_y) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, log_y ? "%.0e" : "%.3g", log_y ? std::pow(10.0, v) : v);
  return buffer;
}

}  // namespace

void write_line_chart(const std::filesystem::path& path, const LineChart& chart) {
  const int left = 80, right = 170, top = 40, bottom = 55;
  cv::Mat image(chart.height, chart.width, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Rect plot(left, top, chart.width - left - right, chart.height - top - bottom);

  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  const auto value = [&](double y) { return chart.log_y ? std::log10(y) : y; };
  for (const ChartSeries& s : chart.series) {
    if (s.x.size() != s.y.size())
      throw std::invalid_argument("line chart '" + chart.title + "': series '" + s.label +
                                  "' has x and y of different lengths");
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const double v = value(s.y[i]);
      if (!std::isfinite(v) || !std::isfinite(s.x[i])) continue;
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, v);
      y1 = std::max(y1, v);
    }
  }
  if (!(x1 > x0)) x1 = x0 + 1.0;
  if (!std::isfinite(x0)) x0 = 0.0, x1 = 1.0;
  if (!std::isfinite(y0)) y0 = 0.0, y1 = 1.0;
  if (!chart.log_y) y0 = std::min(y0, 0.0);
  if (!(y1 > y0)) y1 = y0 + 1.0;
  const auto px = [&](double x) { return plot.x + (x - x0) / (x1 - x0) * plot.width; };
  const auto py = [&](double v) {
    return plot.y + plot.height - (v - y0) / (y1 - y0) * plot.height;
  };

  const cv::Scalar grey(200, 200, 200), black(0, 0, 0);
  const int font = cv::FONT_HERSHEY_SIMPLEX;
  for (int i = 0; i <= 5; ++i) {
    const double v = y0 + (y1 - y0) * i / 5.0;
    const int y = static_cast<int>(py(v));
    cv::line(image, {plot.x, y}, {plot.x + plot.width, y}, grey, 1);
    cv::putText(image, tick_text(v, chart.log_y), {5, y + 4}, font, 0.4, black, 1, cv::LINE_AA);
    const double xv = x0 + (x1 - x0) * i / 5.0;
    const int x = static_cast<int>(px(xv));
    cv::line(image, {x, plot.y}, {x, plot.y + plot.height}, grey, 1);
    cv::putText(image, tick_text(xv, false), {x - 12, plot.y + plot.height + 18}, font, 0.4, black,
                1, cv::LINE_AA);
  }
  cv::rectangle(image, plot, black, 1);
  cv::putText(image, chart.title, {left, 25}, font, 0.6, black, 1, cv::LINE_AA);
  cv::putText(image, chart.x_label, {plot.x + plot.width / 2 - 30, chart.height - 12}, font, 0.45,
              black, 1, cv::LINE_AA);
  cv::putText(image, chart.y_label, {5, plot.y - 8}, font, 0.45, black, 1, cv::LINE_AA);

  int legend_y = plot.y + 15;
  for (const ChartSeries& s : chart.series) {
    const cv::Scalar colour(s.b, s.g, s.r);
    for (std::size_t i = 1; i < s.x.size(); ++i) {
      const double a = value(s.y[i - 1]), b = value(s.y[i]);
      if (!std::isfinite(a) || !std::isfinite(b)) continue;
      cv::line(image, cv::Point2d(px(s.x[i - 1]), py(a)), cv::Point2d(px(s.x[i]), py(b)), colour, 2,
               cv::LINE_AA);
    }
    const int lx = plot.x + plot.width + 12;
    cv::line(image, {lx, legend_y - 4}, {lx + 25, legend_y - 4}, colour, 3);
    cv::putText(image, s.label, {lx + 32, legend_y}, font, 0.45, black, 1, cv::LINE_AA);
    legend_y += 20;
  }
  if (!cv::imwrite(path.string(), image))
    throw std::runtime_error("cannot write the figure " + path.string());
}

}  // namespace opf
