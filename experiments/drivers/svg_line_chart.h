#pragma once
// A LineChart as SVG: the vector form of the PNG that line_chart.h writes, for print at any size.
// Both draw from chart_layout.h: the same axes, ticks, labels, bands, reference lines, legend,
// and every series in its colour, dash style and markers. Text is <text> (selectable, in a
// sans-serif font); "~" after a character becomes a combining tilde (U+0303), "Q~" as Q̃.

#include "drivers/line_chart.h"

#include <filesystem>
#include <string>

namespace opf {

/// `text` for SVG content or attributes: &, <, > and " escaped, "~" after a character as U+0303.
std::string svg_text(const std::string& text);

/// The chart as a standalone SVG document of width x height px. Each run of finite points of a
/// series is one <polyline class="series">; markers are class "marker", clip marks "clip-mark",
/// reference lines class "reference". Throws std::invalid_argument for a series whose x and y
/// differ in length.
std::string svg_line_chart(const LineChart& chart);

/// Writes svg_line_chart to `path` (all or nothing); throws std::runtime_error naming the path
/// when it cannot be written.
void write_svg_line_chart(const std::filesystem::path& path, const LineChart& chart);

}  // namespace opf
