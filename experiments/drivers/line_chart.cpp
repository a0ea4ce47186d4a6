#include "drivers/line_chart.h"

#include "drivers/chart_layout.h"
#include "drivers/png_resolution.h"
#include "opf/io/atomic_file.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace opf {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
const cv::Scalar kBlack(0, 0, 0);
const cv::Scalar kWhite(255, 255, 255);
const cv::Scalar kBandGrey(228, 228, 228);
const cv::Scalar kGrid(215, 215, 215);

/// The image being drawn: positions and sizes come in layout px and are drawn times `scale`.
struct Canvas {
  cv::Mat image;
  double scale = 1.0;

  cv::Point2d at(double x, double y) const { return {x * scale, y * scale}; }
  int thickness(double layout_px) const {
    return std::max(1, static_cast<int>(std::lround(layout_px * scale)));
  }
};

cv::Scalar colour_of(const ChartSeries& s) {
  return {double(s.b), double(s.g), double(s.r)};
}

/// Text at baseline (x, y), where "~" after a character draws a tilde above that character.
void draw_text(Canvas& canvas, const std::string& text, double x, double y, double font) {
  std::string plain;
  std::vector<std::size_t> marked;  // indices in `plain` of characters with a tilde
  for (const char c : text) {
    if (c == '~' && !plain.empty())
      marked.push_back(plain.size() - 1);
    else
      plain += c;
  }
  const double scale = font * canvas.scale;
  const int thickness = canvas.thickness(1.0);
  const cv::Point origin = canvas.at(x, y);
  cv::putText(canvas.image, plain, origin, kFont, scale, kBlack, thickness, cv::LINE_AA);
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
    cv::polylines(canvas.image, wave, false, kBlack, thickness, cv::LINE_AA);
  }
}

/// A polyline (image px) drawn in the style's pattern, the pattern running on across its vertices.
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

/// A polygon in layout px around (x, y), filled and outlined, with subpixel vertices.
void draw_polygon(Canvas& canvas, const std::vector<std::array<double, 2>>& outline, double x,
                  double y, const cv::Scalar& fill, const cv::Scalar& edge) {
  constexpr int kShift = 4;  // vertices in 1/16 px
  std::vector<cv::Point> points;
  for (const auto& [dx, dy] : outline)
    points.emplace_back(int(std::lround((x + dx) * canvas.scale * 16.0)),
                        int(std::lround((y + dy) * canvas.scale * 16.0)));
  cv::fillPoly(canvas.image, std::vector<std::vector<cv::Point>>{points}, fill, cv::LINE_AA,
               kShift);
  cv::polylines(canvas.image, points, true, edge, canvas.thickness(0.5), cv::LINE_AA, kShift);
}

/// A marker centred on (x, y) in layout px: filled in the colour with a white edge, so that
/// markers on top of each other keep their outlines; a cross as two strokes.
void draw_marker(Canvas& canvas, Marker marker, double x, double y, const cv::Scalar& colour) {
  const double size = ChartLayout::kMarkerSize, h = 0.5 * size;
  if (marker == Marker::kCircle) {
    const cv::Point centre = canvas.at(x, y);
    const int radius = static_cast<int>(std::lround(0.85 * h * canvas.scale));
    cv::circle(canvas.image, centre, radius, colour, cv::FILLED, cv::LINE_AA);
    cv::circle(canvas.image, centre, radius, kWhite, canvas.thickness(0.5), cv::LINE_AA);
  } else if (marker == Marker::kCross) {
    for (const double s : {-1.0, 1.0})
      cv::line(canvas.image, canvas.at(x - h, y - s * h), canvas.at(x + h, y + s * h), colour,
               canvas.thickness(2.0), cv::LINE_AA);
  } else if (marker != Marker::kNone) {
    draw_polygon(canvas, marker_polygon(marker, size), x, y, colour, kWhite);
  }
}

/// The upward triangle that marks a value above the clip, its tip at the clip's line.
void draw_clip_mark(Canvas& canvas, double x, double y, const cv::Scalar& colour) {
  draw_polygon(canvas, {{0.0, 0.5}, {4.5, 9.0}, {-4.5, 9.0}}, x, y, colour, kBlack);
}

/// Shaded bands, grid lines with their ticks' text, and the reference lines.
void draw_axes(Canvas& canvas, const LineChart& chart, const ChartLayout& l) {
  const double top = l.plot_top, bottom = l.plot_top + l.plot_height;
  const double left = l.plot_left, right = l.plot_left + l.plot_width;
  for (const ChartBand& band : chart.bands) {
    const double a = std::clamp(l.px(band.from), left, right);
    const double b = std::clamp(l.px(band.to), left, right);
    if (b > a) cv::rectangle(canvas.image, canvas.at(a, top), canvas.at(b, bottom), kBandGrey, -1);
  }
  const double y_step = l.y.ticks.size() > 1 ? l.y.ticks[1] - l.y.ticks[0] : 1.0;
  for (const double v : l.y.ticks) {
    const double y = l.py(v);
    cv::line(canvas.image, canvas.at(left, y), canvas.at(right, y), kGrid, canvas.thickness(1.0));
    const std::string text = tick_text(v, y_step, chart.log_y);
    draw_text(canvas, text, left - 7.0 - text_width(text, kTickFont), y + 5.0, kTickFont);
  }
  const double x_step = l.x.ticks.size() > 1 ? l.x.ticks[1] - l.x.ticks[0] : 1.0;
  for (const double v : l.x.ticks) {
    const double x = l.px(v);
    cv::line(canvas.image, canvas.at(x, top), canvas.at(x, bottom), kGrid, canvas.thickness(1.0));
    const std::string text = tick_text(v, x_step, false);
    draw_text(canvas, text, x - 0.5 * text_width(text, kTickFont), bottom + 20.0, kTickFont);
  }
  for (const ChartReference& r : chart.references) {
    const double y = l.py(plotted_y(chart, r.y));
    draw_styled(canvas.image, {canvas.at(left, y), canvas.at(right, y)}, kBlack,
                canvas.thickness(1.2), LineStyle::kDashed);
  }
}

/// The lines in draw order, then every series' markers and clip marks on top of all lines.
void draw_series(Canvas& canvas, const LineChart& chart, const ChartLayout& l) {
  const std::vector<std::size_t> order = draw_order(chart);
  for (const std::size_t k : order) {
    const ChartSeries& s = chart.series[k];
    std::vector<cv::Point2d> run;
    const auto flush = [&] {
      if (run.size() > 1)
        draw_styled(canvas.image, run, colour_of(s), canvas.thickness(s.width), s.style);
      run.clear();
    };
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const double v = plotted_y(chart, s.y[i]);
      if (!std::isfinite(v) || !std::isfinite(s.x[i])) {
        flush();
        continue;
      }
      run.push_back(canvas.at(l.px(s.x[i]), l.py(v)));
    }
    flush();
  }
  for (const std::size_t k : order) {
    const ChartSeries& s = chart.series[k];
    const SeriesMarks marks = series_marks(chart, s, l);
    for (const auto& [x, y] : marks.markers) draw_marker(canvas, s.marker, x, y, colour_of(s));
    for (const auto& [x, y] : marks.clips) draw_clip_mark(canvas, x, y, colour_of(s));
  }
}

void draw_legend(Canvas& canvas, const LineChart& chart, const ChartLayout& l) {
  using Kind = LegendEntry::Kind;
  const double x = l.legend_left, w = ChartLayout::kSwatch;
  double y = l.legend_top;
  for (const LegendEntry& e : legend_entries(chart)) {
    const double mid = y - 5.0;
    if (e.kind == Kind::kSeries) {
      const ChartSeries& own = chart.series[e.series.front()];
      draw_styled(canvas.image, {canvas.at(x, mid), canvas.at(x + w, mid)}, colour_of(own),
                  canvas.thickness(own.width), own.style);
      for (std::size_t j = 0; j < e.series.size(); ++j) {
        const ChartSeries& s = chart.series[e.series[j]];
        const double at = x + w * (static_cast<double>(j) + 0.5) / double(e.series.size());
        draw_marker(canvas, s.marker, at, mid, colour_of(s));
      }
    } else if (e.kind == Kind::kBand) {
      cv::rectangle(canvas.image, canvas.at(x, y - 11.0), canvas.at(x + w, y + 1.0), kBandGrey, -1);
    } else if (e.kind == Kind::kReference) {
      draw_styled(canvas.image, {canvas.at(x, mid), canvas.at(x + w, mid)}, kBlack,
                  canvas.thickness(1.2), LineStyle::kDashed);
    } else {
      draw_clip_mark(canvas, x + 0.5 * w, y - 10.0, cv::Scalar(150, 150, 150));
    }
    draw_text(canvas, e.text, x + w + 6.0, y, kLegendFont);
    y += ChartLayout::kRow;
  }
}

void write_png(const std::filesystem::path& path, const cv::Mat& image) {
  std::vector<std::uint8_t> png;
  if (!cv::imencode(".png", image, png))
    throw std::runtime_error("cannot encode the figure " + path.string());
  png = with_png_resolution(png, kPngDotsPerInch);
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  });
}

}  // namespace

void write_line_chart(const std::filesystem::path& path, const LineChart& chart) {
  const ChartLayout l = layout_chart(chart);
  const double scale = std::max(1, chart.png_scale);
  Canvas canvas{cv::Mat(static_cast<int>(std::lround(l.height * scale)),
                        static_cast<int>(std::lround(l.width * scale)), CV_8UC3, kWhite),
                scale};
  draw_axes(canvas, chart, l);
  // The lines on a copy of which only the plot goes back: they are clipped to the plot.
  Canvas lines{canvas.image.clone(), scale};
  draw_series(lines, chart, l);
  const cv::Rect plot(canvas.at(l.plot_left, l.plot_top),
                      canvas.at(l.plot_left + l.plot_width, l.plot_top + l.plot_height));
  lines.image(plot).copyTo(canvas.image(plot));
  cv::rectangle(canvas.image, plot, kBlack, canvas.thickness(1.0));

  draw_text(canvas, chart.title, l.plot_left, 28.0, kTitleFont);
  draw_text(canvas, chart.y_label, 8.0, l.plot_top - 12.0, kLabelFont);
  draw_text(canvas, chart.x_label,
            l.plot_left + 0.5 * (l.plot_width - text_width(chart.x_label, kLabelFont)),
            l.height - 12.0, kLabelFont);
  draw_legend(canvas, chart, l);
  write_png(path, canvas.image);
}

}  // namespace opf
