#include "drivers/svg_line_chart.h"

#include "drivers/chart_layout.h"
#include "opf/io/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace opf {
namespace {

constexpr const char* kBandGrey = "#e4e4e4";
constexpr const char* kGrid = "#d7d7d7";

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  return buffer;
}

std::string colour_of(const ChartSeries& s) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", s.r, s.g, s.b);
  return buffer;
}

/// The stroke of a line `width` px wide in a style: colour, width and dash pattern.
std::string stroke(const std::string& colour, double width, LineStyle style) {
  std::string s = "fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"" + number(width) + "\"";
  const std::vector<double> pattern = dash_pattern(style, width);
  if (!pattern.empty()) {
    s += " stroke-dasharray=\"";
    for (std::size_t i = 0; i < pattern.size(); ++i) {
      if (i > 0) s += ',';
      s += number(pattern[i]);
    }
    s += "\"";
  }
  return s;
}

std::string line(double x0, double y0, double x1, double y1, const std::string& attributes) {
  return std::string("<line x1=\"") + number(x0) + "\" y1=\"" + number(y0) + "\" x2=\"" +
         number(x1) + "\" y2=\"" + number(y1) + "\" " + attributes + "/>\n";
}

std::string text(double x, double y, double font, const std::string& content,
                 const std::string& attributes = "") {
  return std::string("<text x=\"") + number(x) + "\" y=\"" + number(y) + "\" font-size=\"" +
         number(font * kSvgFontPx) + "\"" + (attributes.empty() ? "" : " " + attributes) + ">" +
         svg_text(content) + "</text>\n";
}

std::string polygon_path(const std::vector<std::array<double, 2>>& outline, double x, double y) {
  std::string d;
  for (std::size_t i = 0; i < outline.size(); ++i)
    d.append(i > 0 ? " L" : "M")
        .append(number(x + outline[i][0]))
        .append(" ")
        .append(number(y + outline[i][1]));
  return d + " Z";
}

/// A marker centred on (x, y), as line_chart.cpp draws it: filled, white-edged; a cross in strokes.
std::string marker(Marker m, double x, double y, const std::string& colour) {
  const double size = ChartLayout::kMarkerSize, h = 0.5 * size;
  if (m == Marker::kNone) return "";
  if (m == Marker::kCircle)
    return std::string("<circle class=\"marker\" cx=\"") + number(x) + "\" cy=\"" + number(y) +
           "\" r=\"" + number(0.85 * h) + "\" fill=\"" + colour +
           "\" stroke=\"#ffffff\" stroke-width=\"0.5\"/>\n";
  if (m == Marker::kCross)
    return std::string("<path class=\"marker\" d=\"M") + number(x - h) + " " + number(y - h) +
           " L" + number(x + h) + " " + number(y + h) + " M" + number(x - h) + " " + number(y + h) +
           " L" + number(x + h) + " " + number(y - h) + "\" " +
           stroke(colour, 2.0, LineStyle::kSolid) + "/>\n";
  return std::string("<path class=\"marker\" d=\"") + polygon_path(marker_polygon(m, size), x, y) +
         "\" fill=\"" + colour + "\" stroke=\"#ffffff\" stroke-width=\"0.5\"/>\n";
}

std::string clip_mark(double x, double y, const std::string& colour) {
  return std::string("<path class=\"clip-mark\" d=\"") +
         polygon_path({{0.0, 0.5}, {4.5, 9.0}, {-4.5, 9.0}}, x, y) + "\" fill=\"" + colour +
         "\" stroke=\"#000000\" stroke-width=\"0.5\"/>\n";
}

/// Bands, grid lines, ticks' text.
void write_axes(std::ostream& out, const LineChart& chart, const ChartLayout& l) {
  const double top = l.plot_top, bottom = l.plot_top + l.plot_height;
  const double left = l.plot_left, right = l.plot_left + l.plot_width;
  for (const ChartBand& band : chart.bands) {
    const double a = std::clamp(l.px(band.from), left, right);
    const double b = std::clamp(l.px(band.to), left, right);
    if (b > a)
      out << "<rect class=\"band\" x=\"" << number(a) << "\" y=\"" << number(top) << "\" width=\""
          << number(b - a) << "\" height=\"" << number(l.plot_height) << "\" fill=\"" << kBandGrey
          << "\"/>\n";
  }
  const std::string grid = std::string("stroke=\"") + kGrid + "\" stroke-width=\"1\"";
  const double y_step = l.y.ticks.size() > 1 ? l.y.ticks[1] - l.y.ticks[0] : 1.0;
  for (const double v : l.y.ticks) {
    out << line(left, l.py(v), right, l.py(v), grid);
    out << text(left - 7.0, l.py(v) + 5.0, kTickFont, tick_text(v, y_step, chart.log_y),
                "text-anchor=\"end\"");
  }
  const double x_step = l.x.ticks.size() > 1 ? l.x.ticks[1] - l.x.ticks[0] : 1.0;
  for (const double v : l.x.ticks) {
    out << line(l.px(v), top, l.px(v), bottom, grid);
    out << text(l.px(v), bottom + 20.0, kTickFont, tick_text(v, x_step, false),
                "text-anchor=\"middle\"");
  }
}

/// Inside the plot, clipped to it: the reference lines, the series' lines in draw order, then
/// the markers and clip marks on top.
void write_plot(std::ostream& out, const LineChart& chart, const ChartLayout& l) {
  out << "<g clip-path=\"url(#plot)\">\n";
  for (const ChartReference& r : chart.references)
    out << line(l.plot_left, l.py(plotted_y(chart, r.y)), l.plot_left + l.plot_width,
                l.py(plotted_y(chart, r.y)),
                "class=\"reference\" " + stroke("#000000", 1.2, LineStyle::kDashed));
  const std::vector<std::size_t> order = draw_order(chart);
  for (const std::size_t k : order) {
    const ChartSeries& s = chart.series[k];
    std::string points;
    std::size_t count = 0;  // of `points`
    const auto flush = [&] {
      if (count > 1)
        out << "<polyline class=\"series\" data-label=\"" << svg_text(s.label) << "\" points=\""
            << points << "\" " << stroke(colour_of(s), s.width, s.style) << "/>\n";
      points.clear();
      count = 0;
    };
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const double v = plotted_y(chart, s.y[i]);
      if (!std::isfinite(v) || !std::isfinite(s.x[i])) {
        flush();
        continue;
      }
      points.append(count++ > 0 ? " " : "")
          .append(number(l.px(s.x[i])))
          .append(",")
          .append(number(l.py(v)));
    }
    flush();
  }
  for (const std::size_t k : order) {
    const ChartSeries& s = chart.series[k];
    const SeriesMarks marks = series_marks(chart, s, l);
    for (const auto& [x, y] : marks.markers) out << marker(s.marker, x, y, colour_of(s));
    for (const auto& [x, y] : marks.clips) out << clip_mark(x, y, colour_of(s));
  }
  out << "</g>\n";
}

void write_legend(std::ostream& out, const LineChart& chart, const ChartLayout& l) {
  using Kind = LegendEntry::Kind;
  const double x = l.legend_left, w = ChartLayout::kSwatch;
  double y = l.legend_top;
  out << "<g class=\"legend\">\n";
  for (const LegendEntry& e : legend_entries(chart)) {
    const double mid = y - 5.0;
    if (e.kind == Kind::kSeries) {
      const ChartSeries& own = chart.series[e.series.front()];
      out << line(x, mid, x + w, mid, stroke(colour_of(own), own.width, own.style));
      for (std::size_t j = 0; j < e.series.size(); ++j) {
        const ChartSeries& s = chart.series[e.series[j]];
        out << marker(s.marker, x + w * (double(j) + 0.5) / double(e.series.size()), mid,
                      colour_of(s));
      }
    } else if (e.kind == Kind::kBand) {
      out << "<rect x=\"" << number(x) << "\" y=\"" << number(y - 11.0) << "\" width=\""
          << number(w) << "\" height=\"12\" fill=\"" << kBandGrey << "\"/>\n";
    } else if (e.kind == Kind::kReference) {
      out << line(x, mid, x + w, mid, stroke("#000000", 1.2, LineStyle::kDashed));
    } else {
      out << clip_mark(x + 0.5 * w, y - 10.0, "#969696");
    }
    out << text(x + w + 6.0, y, kLegendFont, e.text);
    y += ChartLayout::kRow;
  }
  out << "</g>\n";
}

}  // namespace

std::string svg_text(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '~' && !out.empty())
      out += "\xcc\x83";  // U+0303 COMBINING TILDE, over the character before
    else if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

std::string svg_line_chart(const LineChart& chart) {
  const ChartLayout l = layout_chart(chart);
  std::ostringstream out;
  const std::string w = number(l.width), h = number(l.height);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
      << "\" viewBox=\"0 0 " << w << " " << h
      << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n"
      << "<title>" << svg_text(chart.title) << "</title>\n"
      << "<defs><clipPath id=\"plot\"><rect x=\"" << number(l.plot_left) << "\" y=\""
      << number(l.plot_top) << "\" width=\"" << number(l.plot_width) << "\" height=\""
      << number(l.plot_height) << "\"/></clipPath></defs>\n"
      << "<rect width=\"" << w << "\" height=\"" << h << "\" fill=\"#ffffff\"/>\n";
  write_axes(out, chart, l);
  write_plot(out, chart, l);
  out << "<rect class=\"frame\" x=\"" << number(l.plot_left) << "\" y=\"" << number(l.plot_top)
      << "\" width=\"" << number(l.plot_width) << "\" height=\"" << number(l.plot_height)
      << "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
  out << text(l.plot_left, 28.0, kTitleFont, chart.title, "class=\"title\"");
  out << text(8.0, l.plot_top - 12.0, kLabelFont, chart.y_label, "class=\"y-label\"");
  out << text(l.plot_left + 0.5 * l.plot_width, l.height - 12.0, kLabelFont, chart.x_label,
              "class=\"x-label\" text-anchor=\"middle\"");
  write_legend(out, chart, l);
  out << "</svg>\n";
  return out.str();
}

void write_svg_line_chart(const std::filesystem::path& path, const LineChart& chart) {
  const std::string svg = svg_line_chart(chart);
  write_file_atomically(path, [&](std::ostream& out) { out << svg; });
}

}  // namespace opf
