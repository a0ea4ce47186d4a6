#include "drivers/coinciding_series.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace opf {
namespace {

ChartSeries constant(const std::string& label, double value) {
  return ChartSeries{label, {0, 1, 2}, {value, value, value}, 0, 0, 0};
}

TEST(CoincidingSeries, SameValuesWithinARelativeBillionthAndGapsAlike) {
  ChartSeries a = constant("a", 0.0078), b = constant("b", 0.0078 * (1 + 1e-12));
  EXPECT_TRUE(same_values(a, b));
  b.y[1] = 0.0079;
  EXPECT_FALSE(same_values(a, b));
  a.y[1] = b.y[1] = std::nan("");
  EXPECT_TRUE(same_values(a, b));
  b.x[2] = 3.0;
  EXPECT_FALSE(same_values(a, b));
}

TEST(CoincidingSeries, TheBaselinesConstantTracesShareALegendEntry) {
  // The trace figure: the OPF grows while hidden; the PF, CVKF and OAPF report the same constant
  // trace, the IMM another.
  std::vector<ChartSeries> series = {ChartSeries{"opf", {0, 1, 2}, {0.0078, 0.02, 0.0078}, 0, 0, 0},
                                     constant("pf", 0.0078), constant("cvkf", 0.0078),
                                     constant("imm", 0.0013), constant("oapf", 0.0078)};
  const auto groups = merge_coinciding_series(series);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0], (std::vector<std::size_t>{1, 2, 4}));
  EXPECT_EQ(series[1].label, "pf = cvkf = oapf");
  EXPECT_EQ(series[1].coinciding, (std::vector<std::size_t>{2, 4}));
  EXPECT_TRUE(series[1].in_legend);
  EXPECT_FALSE(series[2].in_legend);
  EXPECT_FALSE(series[4].in_legend);
  // Each member's markers a third of the spacing after the previous one's.
  EXPECT_DOUBLE_EQ(series[1].marker_phase, 0.0);
  EXPECT_DOUBLE_EQ(series[2].marker_phase, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(series[4].marker_phase, 2.0 / 3.0);
  // The others as they were.
  EXPECT_EQ(series[0].label, "opf");
  EXPECT_EQ(series[3].label, "imm");
  EXPECT_TRUE(series[3].in_legend && series[3].coinciding.empty());
}

TEST(CoincidingSeries, NoGroupLeavesTheSeriesAlone) {
  std::vector<ChartSeries> series = {constant("opf", 1.0), constant("pf", 2.0)};
  series[1].marker_phase = 0.5;
  EXPECT_TRUE(merge_coinciding_series(series).empty());
  EXPECT_EQ(series[1].label, "pf");
  EXPECT_DOUBLE_EQ(series[1].marker_phase, 0.5);
}

}  // namespace
}  // namespace opf
