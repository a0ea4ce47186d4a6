#include "drivers/estimator_style.h"

#include <algorithm>

namespace opf::experiments {

EstimatorStyle estimator_style(const std::string& estimator) {
  // In kFigureOrder's order. Widths: the PF widest, the OAPF (often on the PF's values) inside
  // it, the OPF and the Kalman filters on top.
  static constexpr std::array<EstimatorStyle, kFigureOrder.size()> kStyles = {{
      {{220, 30, 30}, LineStyle::kSolid, 2, Marker::kDiamond},
      {{30, 60, 220}, LineStyle::kDashed, 4, Marker::kSquare},
      {{30, 160, 60}, LineStyle::kDashDot, 2, Marker::kTriangleUp},
      {{140, 60, 200}, LineStyle::kDashed, 2, Marker::kTriangleDown},
      {{240, 140, 0}, LineStyle::kDotted, 3, Marker::kCross},
  }};
  const auto it = std::find(kFigureOrder.begin(), kFigureOrder.end(), estimator);
  if (it == kFigureOrder.end()) return {{90, 90, 90}, LineStyle::kSolid, 1, Marker::kCircle};
  return kStyles[static_cast<std::size_t>(it - kFigureOrder.begin())];
}

std::vector<std::string> in_figure_order(const std::vector<std::string>& estimators) {
  std::vector<std::string> ordered;
  for (const std::string_view name : kFigureOrder)
    if (std::find(estimators.begin(), estimators.end(), name) != estimators.end())
      ordered.emplace_back(name);
  for (const std::string& name : estimators)
    if (std::find(ordered.begin(), ordered.end(), name) == ordered.end()) ordered.push_back(name);
  return ordered;
}

ChartSeries estimator_series(const std::string& label, const std::string& estimator,
                             double marker_phase) {
  const EstimatorStyle style = estimator_style(estimator);
  ChartSeries series;
  series.label = label;
  series.r = style.rgb[0];
  series.g = style.rgb[1];
  series.b = style.rgb[2];
  series.style = style.line;
  series.width = style.width;
  series.marker = style.marker;
  series.marker_phase = marker_phase;
  return series;
}

}  // namespace opf::experiments
