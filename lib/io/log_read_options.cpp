#include "io/log_read_options.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace opf {
namespace {

constexpr std::array<std::pair<std::string_view, TimeUnit>, 4> kTimeUnits = {{
    {"s", TimeUnit::kSeconds},
    {"ms", TimeUnit::kMilliseconds},
    {"us", TimeUnit::kMicroseconds},
    {"ns", TimeUnit::kNanoseconds},
}};
constexpr std::array<std::pair<std::string_view, LengthUnit>, 2> kLengthUnits = {{
    {"m", LengthUnit::kMetres},
    {"mm", LengthUnit::kMillimetres},
}};
constexpr std::array<std::string_view, 9> kCanonicalColumns = {"t",  "object", "x",  "y", "z",
                                                               "qx", "qy",     "qz", "qw"};

}  // namespace

std::optional<TimeUnit> parse_time_unit(std::string_view name) {
  for (const auto& [word, unit] : kTimeUnits)
    if (word == name) return unit;
  return std::nullopt;
}

std::optional<LengthUnit> parse_length_unit(std::string_view name) {
  for (const auto& [word, unit] : kLengthUnits)
    if (word == name) return unit;
  return std::nullopt;
}

std::string_view to_string(TimeUnit unit) {
  for (const auto& [word, u] : kTimeUnits)
    if (u == unit) return word;
  return "?";
}

std::string_view to_string(LengthUnit unit) {
  for (const auto& [word, u] : kLengthUnits)
    if (u == unit) return word;
  return "?";
}

double seconds_per(TimeUnit unit) {
  switch (unit) {
    case TimeUnit::kSeconds:
      return 1.0;
    case TimeUnit::kMilliseconds:
      return 1e-3;
    case TimeUnit::kMicroseconds:
      return 1e-6;
    case TimeUnit::kNanoseconds:
      return 1e-9;
  }
  return 1.0;
}

double metres_per(LengthUnit unit) {
  return unit == LengthUnit::kMillimetres ? 1e-3 : 1.0;
}

std::string mapped_column(const LogReadOptions& options, std::string_view canonical) {
  for (const auto& [name, column] : options.columns)
    if (name == canonical) return column;
  return std::string(canonical);
}

std::vector<std::pair<std::string, std::string>> parse_column_mapping(std::string_view text) {
  std::vector<std::pair<std::string, std::string>> mapping;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view entry = text.substr(start, comma - start);
    start = comma + 1;
    if (entry.empty()) continue;
    const std::size_t eq = entry.find('=');
    if (eq == std::string_view::npos || eq == 0 || eq + 1 == entry.size())
      throw std::invalid_argument("'" + std::string(entry) +
                                  "' is not NAME=COLUMN (e.g. qx=rx: the column rx holds qx)");
    const std::string name(entry.substr(0, eq));
    const std::string column(entry.substr(eq + 1));
    if (std::find(kCanonicalColumns.begin(), kCanonicalColumns.end(), name) ==
        kCanonicalColumns.end())
      throw std::invalid_argument("'" + name +
                                  "' is not a column of the log format (t, object, x, y, z, qx, "
                                  "qy, qz, qw)");
    for (const auto& [n, c] : mapping) {
      if (n == name) throw std::invalid_argument("'" + name + "' is mapped twice");
      if (c == column)
        throw std::invalid_argument("the column '" + column + "' is mapped to both " + n + " and " +
                                    name);
    }
    mapping.emplace_back(name, column);
  }
  if (mapping.empty()) throw std::invalid_argument("expected NAME=COLUMN entries, e.g. qx=rx");
  return mapping;
}

}  // namespace opf
