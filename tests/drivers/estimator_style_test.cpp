#include "drivers/estimator_style.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace opf::experiments {
namespace {

TEST(EstimatorStyle, TheFiveEstimatorsDifferInColourLineAndMarker) {
  std::set<std::array<std::uint8_t, 3>> colours;
  std::set<Marker> markers;
  std::set<std::tuple<LineStyle, int>> lines;
  for (const std::string_view name : kFigureOrder) {
    const EstimatorStyle style = estimator_style(std::string(name));
    colours.insert(style.rgb);
    markers.insert(style.marker);
    lines.insert({style.line, style.width});
    EXPECT_NE(style.marker, Marker::kNone) << name;
  }
  EXPECT_EQ(kFigureOrder.size(), 5u);
  EXPECT_EQ(colours.size(), 5u);
  EXPECT_EQ(markers.size(), 5u);
  EXPECT_EQ(lines.size(), 5u);
}

TEST(EstimatorStyle, EachEstimatorLooksTheSameInEveryFigure) {
  // Fixed by name, as the notebooks have them (notebooks/opf_results.py): the OPF a red solid
  // line with diamonds, the PF a wide blue dashed one with squares.
  const EstimatorStyle opf = estimator_style("opf");
  EXPECT_EQ(opf.rgb, (std::array<std::uint8_t, 3>{220, 30, 30}));
  EXPECT_EQ(opf.line, LineStyle::kSolid);
  EXPECT_EQ(opf.marker, Marker::kDiamond);
  const EstimatorStyle pf = estimator_style("pf");
  EXPECT_EQ(pf.rgb, (std::array<std::uint8_t, 3>{30, 60, 220}));
  EXPECT_EQ(pf.marker, Marker::kSquare);
  EXPECT_GT(pf.width, estimator_style("oapf").width);  // drawn first, the OAPF inside it
  EXPECT_EQ(estimator_style("cvkf").marker, Marker::kTriangleUp);
  EXPECT_EQ(estimator_style("imm").marker, Marker::kTriangleDown);
  EXPECT_EQ(estimator_style("oapf").marker, Marker::kCross);
  // The same series whatever the other estimators of the figure.
  const ChartSeries a = estimator_series("cvkf", "cvkf", 0.25);
  const ChartSeries b = estimator_series("cvkf", "cvkf", 0.25);
  EXPECT_EQ(std::tie(a.r, a.g, a.b, a.style, a.width, a.marker, a.marker_phase),
            std::tie(b.r, b.g, b.b, b.style, b.width, b.marker, b.marker_phase));
  EXPECT_EQ(a.marker_phase, 0.25);
  // A name the figures do not know: grey, thin, circles.
  EXPECT_EQ(estimator_style("mine").marker, Marker::kCircle);
  EXPECT_EQ(estimator_style("mine").width, 1);
}

TEST(EstimatorStyle, FiguresListEstimatorsInOneOrder) {
  EXPECT_EQ(in_figure_order({"oapf", "mine", "cvkf", "opf"}),
            (std::vector<std::string>{"opf", "cvkf", "oapf", "mine"}));
  EXPECT_EQ(in_figure_order({"imm", "pf"}), (std::vector<std::string>{"pf", "imm"}));
}

}  // namespace
}  // namespace opf::experiments
