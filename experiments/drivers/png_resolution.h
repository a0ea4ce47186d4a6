#pragma once
// A PNG's stated resolution (its pHYs chunk): OpenCV's PNG writer has no option for it, so the
// charts' PNGs get it inserted into the encoded bytes, and print at their size rather than at a
// viewer's guess of 72 or 96 dpi.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace opf {

/// `png` (a whole PNG file) with a pHYs chunk stating `dots_per_inch` in both directions right
/// after its header chunk, any pHYs it had dropped. Throws std::invalid_argument when `png` does
/// not start with the PNG signature and a header chunk.
std::vector<std::uint8_t> with_png_resolution(std::span<const std::uint8_t> png,
                                              double dots_per_inch);

/// The resolution in dots per inch that a PNG's pHYs chunk states; none without one, with one in
/// unknown units (an aspect ratio only), or for bytes that are not a PNG.
std::optional<double> png_resolution(std::span<const std::uint8_t> png);

}  // namespace opf
