#include "opf/io/log_read_options.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace opf {
namespace {

// Each unit with its name and its size in seconds or metres.
template <class Unit>
struct UnitEntry {
  std::string_view name;
  Unit unit;
  double size;
};
constexpr std::array<UnitEntry<TimeUnit>, 4> kTimeUnits = {{
    {"s", TimeUnit::kSeconds, 1.0},
    {"ms", TimeUnit::kMilliseconds, 1e-3},
    {"us", TimeUnit::kMicroseconds, 1e-6},
    {"ns", TimeUnit::kNanoseconds, 1e-9},
}};
constexpr std::array<UnitEntry<LengthUnit>, 2> kLengthUnits = {{
    {"m", LengthUnit::kMetres, 1.0},
    {"mm", LengthUnit::kMillimetres, 1e-3},
}};

template <class Unit, std::size_t N>
const UnitEntry<Unit>* find_unit(const std::array<UnitEntry<Unit>, N>& table, Unit unit) {
  for (const auto& entry : table)
    if (entry.unit == unit) return &entry;
  return nullptr;
}

template <class Unit, std::size_t N>
std::optional<Unit> parse_unit(const std::array<UnitEntry<Unit>, N>& table, std::string_view name) {
  for (const auto& entry : table)
    if (entry.name == name) return entry.unit;
  return std::nullopt;
}

}  // namespace

std::optional<LogFormat> parse_log_format(std::string_view name) {
  if (name == "csv") return LogFormat::kCsv;
  if (name == "tum") return LogFormat::kTum;
  if (name == "mot") return LogFormat::kMot;
  if (name == "euroc") return LogFormat::kEuroc;
  if (name == "kitti") return LogFormat::kKitti;
  return std::nullopt;
}

std::optional<TimeUnit> stated_time_unit(const LogReadOptions& options) {
  if (options.time_unit) return options.time_unit;
  if (options.format == LogFormat::kEuroc) return TimeUnit::kNanoseconds;
  return std::nullopt;
}

std::optional<TimeUnit> parse_time_unit(std::string_view name) {
  return parse_unit(kTimeUnits, name);
}

std::optional<LengthUnit> parse_length_unit(std::string_view name) {
  return parse_unit(kLengthUnits, name);
}

std::string_view to_string(TimeUnit unit) {
  return find_unit(kTimeUnits, unit)->name;
}

std::string_view to_string(LengthUnit unit) {
  return find_unit(kLengthUnits, unit)->name;
}

double seconds_per(TimeUnit unit) {
  return find_unit(kTimeUnits, unit)->size;
}

double metres_per(LengthUnit unit) {
  return find_unit(kLengthUnits, unit)->size;
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
    if (std::find(kLogColumns.begin(), kLogColumns.end(), name) == kLogColumns.end())
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
  // Onto a column another name still reads by default (object=t): two fields from one column.
  for (const auto& entry : mapping) {
    const std::string& name = entry.first;
    const std::string& column = entry.second;
    const bool renamed = std::any_of(mapping.begin(), mapping.end(),
                                     [&](const auto& other) { return other.first == column; });
    if (column != name && !renamed &&
        std::find(kLogColumns.begin(), kLogColumns.end(), column) != kLogColumns.end())
      throw std::invalid_argument("'" + name + "=" + column + "' reads " + name +
                                  " from the column that " + column + " reads too; map " + column +
                                  " elsewhere as well");
  }
  return mapping;
}

}  // namespace opf
