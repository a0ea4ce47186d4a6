#pragma once
// How each estimator is drawn in every figure, so that the same estimator looks the same
// everywhere: the paper's colours (OPF red, PF blue; the other baselines green, purple and
// orange), a line style, width and marker of its own (curves on the same values, grey print and
// colour-blind readers still tell them apart), and one order for legends. The notebooks and the
// report use the same colours, styles and markers (notebooks/opf_results.py).

#include "drivers/line_chart.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace opf::experiments {

struct EstimatorStyle {
  std::array<std::uint8_t, 3> rgb;
  LineStyle line;
  int width;  ///< px; wider lines are drawn first
  Marker marker;
};

/// The registered estimators in the order figures list them.
inline constexpr std::array<std::string_view, 5> kFigureOrder = {"opf", "pf", "cvkf", "imm",
                                                                 "oapf"};

/// An estimator's style; a grey thin solid line with circles for a name not in kFigureOrder.
EstimatorStyle estimator_style(const std::string& estimator);

/// `estimators` in figure order: those of kFigureOrder in its order, then the others as given.
std::vector<std::string> in_figure_order(const std::vector<std::string>& estimators);

/// A series labelled `label` drawn in the style of `estimator`, its markers `marker_phase` of the
/// way into their spacing (see ChartSeries).
ChartSeries estimator_series(const std::string& label, const std::string& estimator,
                             double marker_phase = 0.0);

}  // namespace opf::experiments
