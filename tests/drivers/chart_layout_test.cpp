#include "drivers/chart_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

ChartSeries series(std::vector<double> x, std::vector<double> y) {
  ChartSeries s;
  s.x = std::move(x);
  s.y = std::move(y);
  return s;
}

std::vector<double> steps(int n) {
  std::vector<double> x;
  for (int i = 0; i < n; ++i) x.push_back(i);
  return x;
}

TEST(ChartLayout, TicksAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_EQ(nice_ticks(0.0, 10.97, 6), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(nice_ticks(0.0, 0.047, 5), (std::vector<double>{0, 0.01, 0.02, 0.03, 0.04}));
  const std::vector<double> ticks = nice_ticks(-3.0, 7.5, 4);  // step 5 (2.625 raw)
  EXPECT_EQ(ticks, (std::vector<double>{0, 5}));
}

TEST(ChartLayout, TheAlertThresholdLiesInsideTheLogAxisWithAMargin) {
  // The trace figure: values from 10^-3 to 0.02, the alert at 0.1 = 10^-1, a whole decade. The
  // axis used to end at 10^-1, the threshold on the border; now it reaches past it by 5% of the
  // range and so to the next decade.
  LineChart chart;
  chart.log_y = true;
  chart.series = {series({0, 1, 2}, {0.001, 0.005, 0.02})};
  chart.references = {{0.1, "alert (0.1)"}};
  const AxisRange y = y_range(chart);
  EXPECT_DOUBLE_EQ(y.low, -3.0);
  EXPECT_DOUBLE_EQ(y.high, 0.0);
  const double alert = std::log10(0.1), margin = 0.05 * (y.high - y.low);
  EXPECT_GE(y.high - alert, margin);
  EXPECT_GE(alert - y.low, margin);
}

TEST(ChartLayout, AReferenceBelowTheDataAndOnALinearAxisIsInsideToo) {
  LineChart chart;
  chart.series = {series({0, 1}, {2.0, 3.0})};
  chart.references = {{-1.0, "floor"}, {3.0, "ceiling"}};
  const AxisRange y = y_range(chart);
  EXPECT_LT(y.low, -1.0);
  EXPECT_GT(y.high, 3.0 + 0.05 * 4.0 - 1e-12);
  EXPECT_DOUBLE_EQ(y.ticks.back(), y.high);  // the axis ends on a tick
}

TEST(ChartLayout, ACurveLevellingOffAtItsMaximumRunsBelowTheBorder) {
  // twin_mugs: the baselines' error levels off at 0.25 m (where the ball was hidden to where it
  // is carried), which on an axis ending at 0.25 looked clipped.
  LineChart chart;
  chart.series = {series({0, 1, 2, 3}, {0.0, 0.1, 0.2499, 0.2499})};
  const AxisRange y = y_range(chart);
  EXPECT_NEAR(y.high, 0.3, 1e-12);
  EXPECT_DOUBLE_EQ(y.low, 0.0);
}

TEST(ChartLayout, AMapsPathsEndInsideTheFrame) {
  // A top view: x from 0.34 to 0.66, y from -0.22 to 0.26. As a time chart's, the x axis ended on
  // the path's ends and the y axis on its lowest point; a map's reach 5% of each range beyond.
  LineChart chart;
  chart.series = {series({0.34, 0.5, 0.66}, {-0.22, 0.0, 0.26})};
  const AxisRange unpadded_x = x_range(chart), unpadded_y = y_range(chart);
  EXPECT_DOUBLE_EQ(unpadded_x.low, 0.34);
  EXPECT_DOUBLE_EQ(unpadded_y.low, -0.22);
  chart.map = true;
  const AxisRange x = x_range(chart), y = y_range(chart);
  EXPECT_NEAR(x.low, 0.34 - 0.05 * 0.32, 1e-12);
  EXPECT_NEAR(x.high, 0.66 + 0.05 * 0.32, 1e-12);
  EXPECT_NEAR(y.low, -0.22 - 0.05 * 0.48, 1e-12);
  EXPECT_NEAR(y.high, 0.26 + 0.05 * 0.48, 1e-12);
  EXPECT_FALSE(y.ticks.empty());
  for (const double tick : y.ticks) EXPECT_TRUE(tick >= y.low && tick <= y.high) << tick;
}

TEST(ChartLayout, MarkersComeEveryKthPointFromTheSeriesPhase) {
  ChartSeries s = series(steps(120), std::vector<double>(120, 1.0));
  EXPECT_TRUE(marker_points(s).empty());  // no marker, no points
  s.marker = Marker::kSquare;
  const std::vector<std::size_t> first = marker_points(s);
  ASSERT_EQ(first.size(), 12u);  // 120 points, about 12 markers: every 10th
  EXPECT_EQ(first[0], 0u);
  EXPECT_EQ(first[1], 10u);
  s.marker_phase = 0.5;
  const std::vector<std::size_t> second = marker_points(s);
  EXPECT_EQ(second[0], 5u);  // half way between the first series' markers
  s.y[25] = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::size_t> gap = marker_points(s);
  EXPECT_EQ(std::count(gap.begin(), gap.end(), 25u), 0);
  EXPECT_EQ(gap.size(), 11u);
}

TEST(ChartLayout, ClippedPointsMarkEachStretchAboveTheLimit) {
  std::vector<double> y(120, 0.1);
  for (int i = 30; i < 60; ++i) y[i] = 0.4;  // 30 points above 0.25
  y[100] = 0.3;                              // and one alone
  const std::vector<std::size_t> marked = clipped_points(series(steps(120), y), 0.25);
  EXPECT_EQ(marked, (std::vector<std::size_t>{30, 40, 50, 100}));
}

TEST(ChartLayout, TheTopOfAClippedAxisIsTheClipAndTheLegendSaysSo) {
  LineChart chart;
  chart.series = {series({0, 1, 2}, {0.1, 0.9, 0.2})};
  chart.clip = ChartClip{0.25, "clipped at 0.25 m"};
  const AxisRange y = y_range(chart);
  EXPECT_DOUBLE_EQ(y.high, 0.25);
  const std::vector<LegendEntry> legend = legend_entries(chart);
  ASSERT_EQ(legend.size(), 2u);
  EXPECT_EQ(legend.back().kind, LegendEntry::Kind::kClip);
  EXPECT_EQ(legend.back().text, "clipped at 0.25 m");
  // Nothing above the clip: no clip entry, the axis as without one.
  chart.series[0].y[1] = 0.2;
  EXPECT_EQ(legend_entries(chart).size(), 1u);
  EXPECT_GT(y_range(chart).high, 0.2);
}

TEST(ChartLayout, WiderSeriesAreDrawnFirstThenInLegendOrder) {
  LineChart chart;
  for (const int width : {2, 4, 2, 3}) {
    ChartSeries s = series({0, 1}, {0, 1});
    s.width = width;
    chart.series.push_back(s);
  }
  EXPECT_EQ(draw_order(chart), (std::vector<std::size_t>{1, 3, 0, 2}));
}

TEST(ChartLayout, CoincidingSeriesShareOneLegendEntry) {
  LineChart chart;
  chart.series = {series({0}, {1}), series({0}, {1}), series({0}, {1})};
  chart.series[0].label = "pf = oapf";
  chart.series[0].coinciding = {2};
  chart.series[2].in_legend = false;
  chart.series[1].label = "opf";
  chart.references = {{0.5, "alert"}};
  const std::vector<LegendEntry> legend = legend_entries(chart);
  ASSERT_EQ(legend.size(), 3u);
  EXPECT_EQ(legend[0].text, "pf = oapf");
  EXPECT_EQ(legend[0].series, (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(legend[1].text, "opf");
  EXPECT_EQ(legend[2].kind, LegendEntry::Kind::kReference);
}

TEST(ChartLayout, ThePlotLeavesRoomForTheLegendAndMapsItsRange) {
  LineChart chart;
  ChartSeries s = series({0, 10}, {0, 1});
  s.label = "a rather long legend label";
  chart.series = {s};
  const ChartLayout l = layout_chart(chart);
  EXPECT_DOUBLE_EQ(l.width, 900.0);
  EXPECT_LE(l.legend_left + ChartLayout::kSwatch + 6.0 + text_width(s.label, kLegendFont), 900.0);
  EXPECT_DOUBLE_EQ(l.px(0.0), l.plot_left);
  EXPECT_DOUBLE_EQ(l.px(10.0), l.plot_left + l.plot_width);
  EXPECT_DOUBLE_EQ(l.py(l.y.low), l.plot_top + l.plot_height);
  chart.series[0].y.pop_back();
  EXPECT_THROW(layout_chart(chart), std::invalid_argument);
}

}  // namespace
}  // namespace opf
