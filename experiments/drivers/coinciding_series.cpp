#include "drivers/coinciding_series.h"

#include <algorithm>
#include <cmath>

namespace opf {
namespace {

bool same_value(double a, double b) {
  if (!std::isfinite(a) || !std::isfinite(b)) return !std::isfinite(a) && !std::isfinite(b);
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

}  // namespace

bool same_values(const ChartSeries& a, const ChartSeries& b) {
  return a.x == b.x && a.y.size() == b.y.size() &&
         std::equal(a.y.begin(), a.y.end(), b.y.begin(), same_value);
}

std::vector<std::vector<std::size_t>> merge_coinciding_series(std::vector<ChartSeries>& series) {
  std::vector<std::vector<std::size_t>> groups;
  std::vector<bool> grouped(series.size(), false);
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (grouped[i]) continue;
    std::vector<std::size_t> group = {i};
    for (std::size_t j = i + 1; j < series.size(); ++j)
      if (!grouped[j] && same_values(series[i], series[j])) {
        group.push_back(j);
        grouped[j] = true;
      }
    if (group.size() > 1) groups.push_back(std::move(group));
  }
  for (const std::vector<std::size_t>& group : groups) {
    ChartSeries& first = series[group.front()];
    for (std::size_t k = 0; k < group.size(); ++k) {
      ChartSeries& member = series[group[k]];
      member.marker_phase = static_cast<double>(k) / static_cast<double>(group.size());
      if (k == 0) continue;
      member.in_legend = false;
      first.label += " = " + member.label;
      first.coinciding.push_back(group[k]);
    }
  }
  return groups;
}

}  // namespace opf
