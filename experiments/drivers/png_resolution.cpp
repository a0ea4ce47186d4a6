#include "drivers/png_resolution.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string_view>

namespace opf {
namespace {

constexpr std::array<std::uint8_t, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr double kMetresPerInch = 0.0254;

/// The CRC-32 of PNG chunks (ISO 3309), byte by byte from a table of the 256 remainders.
constexpr std::array<std::uint32_t, 256> kCrcTable = [] {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1U) ? 0xedb88320U ^ (c >> 1) : c >> 1;
    table[n] = c;
  }
  return table;
}();

std::uint32_t crc32(std::span<const std::uint8_t> bytes) {
  std::uint32_t c = 0xffffffffU;
  for (const std::uint8_t b : bytes) c = kCrcTable[(c ^ b) & 0xffU] ^ (c >> 8);
  return c ^ 0xffffffffU;
}

std::uint32_t read_u32(std::span<const std::uint8_t> bytes, std::size_t at) {
  return std::uint32_t{bytes[at]} << 24 | std::uint32_t{bytes[at + 1]} << 16 |
         std::uint32_t{bytes[at + 2]} << 8 | std::uint32_t{bytes[at + 3]};
}

void append_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (const int shift : {24, 16, 8, 0}) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

/// A chunk in place: where it starts, its type, where its data starts and its whole length.
struct Chunk {
  std::size_t start = 0;
  std::string_view type;
  std::size_t data = 0;
  std::size_t length = 0;  ///< of the data
  std::size_t end() const { return data + length + 4; }
};

/// The chunks of a PNG, stopping at the first that does not fit in the bytes.
std::vector<Chunk> chunks_of(std::span<const std::uint8_t> png) {
  std::vector<Chunk> chunks;
  if (png.size() < kSignature.size() ||
      !std::equal(kSignature.begin(), kSignature.end(), png.begin()))
    return chunks;
  std::size_t at = kSignature.size();
  while (at + 12 <= png.size()) {
    const std::size_t length = read_u32(png, at);
    if (length > png.size() - at - 12) break;
    chunks.push_back({at, {reinterpret_cast<const char*>(png.data() + at + 4), 4}, at + 8, length});
    at = chunks.back().end();
  }
  return chunks;
}

}  // namespace

std::vector<std::uint8_t> with_png_resolution(std::span<const std::uint8_t> png,
                                              double dots_per_inch) {
  const std::vector<Chunk> chunks = chunks_of(png);
  if (chunks.empty() || chunks.front().type != "IHDR")
    throw std::invalid_argument("with_png_resolution: not a PNG (no signature and header chunk)");
  std::vector<std::uint8_t> out(png.begin(),
                                png.begin() + static_cast<std::ptrdiff_t>(chunks.front().end()));
  // pHYs: pixels per metre in x and y, then the unit (1: the metre).
  std::vector<std::uint8_t> phys = {'p', 'H', 'Y', 's'};
  const auto per_metre = static_cast<std::uint32_t>(std::lround(dots_per_inch / kMetresPerInch));
  append_u32(phys, per_metre);
  append_u32(phys, per_metre);
  phys.push_back(1);
  append_u32(out, static_cast<std::uint32_t>(phys.size() - 4));
  out.insert(out.end(), phys.begin(), phys.end());
  append_u32(out, crc32(phys));
  std::size_t copied = chunks.front().end();
  for (std::size_t i = 1; i < chunks.size(); ++i) {
    if (chunks[i].type != "pHYs")
      out.insert(out.end(), png.begin() + static_cast<std::ptrdiff_t>(chunks[i].start),
                 png.begin() + static_cast<std::ptrdiff_t>(chunks[i].end()));
    copied = chunks[i].end();
  }
  out.insert(out.end(), png.begin() + static_cast<std::ptrdiff_t>(copied), png.end());
  return out;
}

std::optional<double> png_resolution(std::span<const std::uint8_t> png) {
  for (const Chunk& c : chunks_of(png))
    if (c.type == "pHYs" && c.length == 9 && png[c.data + 8] == 1)
      return read_u32(png, c.data) * kMetresPerInch;
  return std::nullopt;
}

}  // namespace opf
