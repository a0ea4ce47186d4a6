#include "track_log_options.h"

#include "opf/io/log_read_arguments.h"

#include <stdexcept>
#include <string_view>

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
  opf::LogArguments given;
  given.format = arguments.format;
  given.object = arguments.object;
  given.time_unit = arguments.time_unit;
  given.length_unit = arguments.length_unit;
  if (!arguments.columns.is_none()) given.columns = column_text(arguments.columns);
  given.frame_tolerance = arguments.frame_tolerance;
  given.rate = arguments.rate;
  given.fill = arguments.fill;
  // Python's names are the library's, but for the one flag: fill=False is --no-fill.
  return log_read_options(given, path, [](std::string_view option) {
    return option == "fill" ? std::string("fill=False") : std::string(option);
  });
}

}  // namespace opf::python
