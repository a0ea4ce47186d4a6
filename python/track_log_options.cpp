#include "track_log_options.h"

#include "opf/io/log_format_detection.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace py = pybind11;

namespace opf::python {
namespace {

// A mapping becomes opf track's text, read by the same parser: the same checks, the same words.
std::string column_text(const py::object& columns) {
  if (py::isinstance<py::str>(columns)) return py::cast<std::string>(columns);
  if (!py::isinstance<py::dict>(columns))
    throw std::invalid_argument(
        "option 'columns': expected a dict {name: column} or the text NAME=COL,..., got " +
        py::cast<std::string>(py::repr(columns)));
  std::string text;
  for (const auto& [name, column] : py::cast<py::dict>(columns)) {
    const bool text_pair = py::isinstance<py::str>(name) && py::isinstance<py::str>(column);
    const std::string entry =
        text_pair ? py::cast<std::string>(name) + "=" + py::cast<std::string>(column)
                  : std::string();
    if (!text_pair || entry.find(',') != std::string::npos)
      throw std::invalid_argument("option 'columns': expected names without commas, got " +
                                  py::cast<std::string>(py::repr(name)) + ": " +
                                  py::cast<std::string>(py::repr(column)));
    text += (text.empty() ? "" : ",") + entry;
  }
  return text;
}

}  // namespace

LogReadOptions log_options_from(const LogArguments& arguments, const std::string& path) {
  LogReadOptions options;
  if (const auto& format = arguments.format) {
    const auto parsed = parse_log_format(*format);
    if (!parsed)
      throw std::invalid_argument("option 'format': expected csv, tum or mot, got \"" + *format +
                                  "\"");
    options.format = *parsed;
  } else {
    options.format = detect_log_format(path);
  }
  options.object = arguments.object;
  if (options.object && options.object->empty())
    throw std::invalid_argument("option 'object' expects a name, got an empty one");
  if (options.format == LogFormat::kTum && !options.object)
    options.object = std::filesystem::path(path).stem().string();
  if (options.format == LogFormat::kTum && !arguments.columns.is_none())
    throw std::invalid_argument("option 'columns' renames CSV columns; a TUM log has none");
  if (const auto& unit = arguments.time_unit) {
    options.time_unit = parse_time_unit(*unit);
    if (!options.time_unit)
      throw std::invalid_argument("option 'time_unit': expected s, ms, us or ns, got \"" + *unit +
                                  "\"");
  }
  if (const auto& unit = arguments.length_unit) {
    options.length_unit = parse_length_unit(*unit);
    if (!options.length_unit)
      throw std::invalid_argument("option 'length_unit': expected m or mm, got \"" + *unit + "\"");
  }
  if (!arguments.columns.is_none()) {
    const std::string text = column_text(arguments.columns);
    try {
      options.columns = parse_column_mapping(text);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("option 'columns': " + std::string(e.what()));
    }
  }
  if (const auto tolerance = arguments.frame_tolerance) {
    if (!(*tolerance >= 0.0) || !std::isfinite(*tolerance))
      throw std::invalid_argument("option 'frame_tolerance' expects seconds >= 0");
    options.frame_tolerance = *tolerance;
  }
  if (const auto rate = arguments.rate) {
    if (!(*rate > 0.0) || !std::isfinite(*rate))
      throw std::invalid_argument("option 'rate' expects a frame rate in Hz > 0");
    options.rate = *rate;
  }
  options.fill_gaps = arguments.fill;
  if (!options.fill_gaps && options.rate)
    throw std::invalid_argument(
        "options 'rate' and 'fill=False' contradict each other: rate sets the rate gaps are "
        "filled at");
  return options;
}

}  // namespace opf::python
