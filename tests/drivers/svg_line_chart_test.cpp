#include "drivers/svg_line_chart.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace opf {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// Whether every element is closed in order (<a><b/></a>), the attributes quoted and no stray
/// '<' or '&' in text: well-formed enough for an XML parser. Returns the first problem or "".
std::string tag_problem(const std::string& svg) {
  std::vector<std::string> open;
  std::size_t at = svg.find("?>");  // past the XML declaration
  at = at == std::string::npos ? 0 : at + 2;
  while ((at = svg.find('<', at)) != std::string::npos) {
    const std::size_t end = svg.find('>', at);
    if (end == std::string::npos) return "unterminated tag";
    const std::string tag = svg.substr(at + 1, end - at - 1);
    if (count(tag, "\"") % 2 != 0) return "unbalanced quotes in <" + tag + ">";
    if (tag.find('<') != std::string::npos) return "'<' inside <" + tag + ">";
    const std::string name =
        tag.substr(tag[0] == '/', tag.find_first_of(" />", 1) - (tag[0] == '/'));
    if (tag[0] == '/') {
      if (open.empty() || open.back() != name) return "</" + name + "> closes nothing open";
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(name);
    }
    const std::size_t next = svg.find('<', end);
    const std::string text = svg.substr(end + 1, next == std::string::npos ? 0 : next - end - 1);
    for (std::size_t amp = text.find('&'); amp != std::string::npos; amp = text.find('&', amp + 1))
      if (text.find(';', amp) == std::string::npos) return "a bare '&' in text";
    at = end + 1;
  }
  return open.empty() ? "" : "<" + open.back() + "> never closed";
}

LineChart example() {
  LineChart chart;
  chart.title = "twin_mugs: ball, trace(Q~) & <things>";
  chart.x_label = "t [s]";
  chart.y_label = "trace(Q~) [m^2 + rad^2]";
  chart.log_y = true;
  ChartSeries opf{"opf", {0, 1, 2, 3, 4}, {0.01, 0.02, std::nan(""), 0.05, 0.01}, 220, 30, 30};
  opf.marker = Marker::kDiamond;
  ChartSeries pf{"pf = cvkf", {0, 1, 2, 3, 4}, {0.01, 0.01, 0.01, 0.01, 0.01}, 30, 60, 220};
  pf.style = LineStyle::kDashed;
  pf.width = 4;
  pf.marker = Marker::kSquare;
  pf.coinciding = {2};
  ChartSeries cvkf = pf;
  cvkf.label = "cvkf";
  cvkf.r = 30, cvkf.g = 160, cvkf.b = 60;
  cvkf.marker = Marker::kTriangleUp;
  cvkf.in_legend = false;
  cvkf.coinciding.clear();
  chart.series = {opf, pf, cvkf};
  chart.bands = {{1.5, 2.5}};
  chart.band_label = "hidden";
  chart.references = {{0.1, "alert (0.1)"}};
  return chart;
}

TEST(SvgLineChart, EscapesTextAndDrawsTheTildeAsACombiningMark) {
  EXPECT_EQ(svg_text("a & b < c > \"d\""), "a &amp; b &lt; c &gt; &quot;d&quot;");
  EXPECT_EQ(svg_text("Q~"), "Q\xcc\x83");
  EXPECT_EQ(svg_text("~"), "~");
}

TEST(SvgLineChart, DrawsEverySegmentMarkerLabelAndTheReference) {
  const LineChart chart = example();
  const std::string svg = svg_line_chart(chart);
  EXPECT_EQ(tag_problem(svg), "");
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("width=\"900.00\" height=\"420.00\""), std::string::npos);
  // One polyline per run of finite points: the OPF's gap splits it in two.
  EXPECT_EQ(count(svg, "<polyline class=\"series\""), 4u);
  EXPECT_EQ(count(svg, "data-label=\"opf\""), 2u);
  // Colours and the dash pattern of the PF's 4 px dashes (6 and 3.5 widths).
  EXPECT_NE(svg.find("stroke=\"#dc1e1e\""), std::string::npos);
  EXPECT_NE(svg.find("stroke=\"#1e3cdc\" stroke-width=\"4.00\" stroke-dasharray=\"24.00,14.00\""),
            std::string::npos);
  // A marker on each series' points (one per point at 5 points), and each in the legend.
  EXPECT_EQ(count(svg, "class=\"marker\""), 4u + 5u + 5u + 3u);
  // The legend: one entry for the coinciding pair, the band, the reference.
  EXPECT_NE(svg.find(">pf = cvkf</text>"), std::string::npos);
  EXPECT_EQ(svg.find(">cvkf</text>"), std::string::npos);
  EXPECT_NE(svg.find(">hidden</text>"), std::string::npos);
  EXPECT_NE(svg.find(">alert (0.1)</text>"), std::string::npos);
  EXPECT_EQ(count(svg, "class=\"reference\""), 1u);
  EXPECT_EQ(count(svg, "class=\"band\""), 1u);
  // Titles and labels as text, escaped, the tilde combining.
  EXPECT_NE(svg.find("trace(Q\xcc\x83) &amp; &lt;things&gt;</text>"), std::string::npos);
  EXPECT_NE(svg.find(">t [s]</text>"), std::string::npos);
  EXPECT_NE(svg.find(">0.1</text>"), std::string::npos);  // a decade's tick
}

TEST(SvgLineChart, MarksClippedValuesAndSaysWhere) {
  LineChart chart;
  chart.series = {ChartSeries{"pf", {0, 1, 2, 3}, {0.1, 0.6, 0.7, 0.1}, 30, 60, 220}};
  chart.clip = ChartClip{0.25, "clipped at 0.25 m"};
  const std::string svg = svg_line_chart(chart);
  EXPECT_EQ(tag_problem(svg), "");
  // Both points above (at 4 points every one carries a mark) and the legend's entry.
  EXPECT_EQ(count(svg, "class=\"clip-mark\""), 3u);
  EXPECT_NE(svg.find(">clipped at 0.25 m</text>"), std::string::npos);
}

TEST(SvgLineChart, WritesTheFileAndNamesAnUnwritablePath) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("opf_svg_line_chart_" + std::to_string(::getpid()) + ".svg");
  write_svg_line_chart(path, example());
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::filesystem::remove(path);
  EXPECT_EQ(text.str(), svg_line_chart(example()));
  EXPECT_THROW(write_svg_line_chart("/nonexistent-dir/figure.svg", example()), std::runtime_error);
  LineChart bad;
  bad.series = {ChartSeries{"bad", {0, 1}, {0}, 0, 0, 0}};
  EXPECT_THROW(svg_line_chart(bad), std::invalid_argument);
}

}  // namespace
}  // namespace opf
