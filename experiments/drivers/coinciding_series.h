#pragma once
// Series on the very same values hide each other: the baselines without the OP update report the
// same constant trace of Q~, one line under another. Such series stay drawn, with their markers
// spread apart, and the legend says which coincide ("pf = cvkf = oapf").

#include "drivers/line_chart.h"

#include <cstddef>
#include <vector>

namespace opf {

/// Whether two series have the same points: equal x, and y equal within a relative 1e-9 or both
/// gaps (non-finite).
bool same_values(const ChartSeries& a, const ChartSeries& b);

/// Finds the groups of series with the same values. In each, the first names all in its label
/// ("pf = cvkf = oapf") and lists the others in `coinciding`; the others leave the legend; the
/// members' marker phases become 0, 1/m, 2/m, ... so that each one's markers show between the
/// others'. Returns the groups (indices into `series`, of two or more each).
std::vector<std::vector<std::size_t>> merge_coinciding_series(std::vector<ChartSeries>& series);

}  // namespace opf
