#include "opf/io/input_error.h"

#include <utility>

namespace opf {

namespace {

std::string describe(const std::string& file, std::size_t line, const std::string& field,
                     const std::string& message, InputError::FieldKind kind) {
  // Appended piece by piece: GCC 12 at -O3 reports a false -Wrestrict on `"literal" + string`.
  std::string text = file;
  if (line > 0) text.append(":").append(std::to_string(line));
  text.append(": ");
  if (!field.empty())
    text.append(kind == InputError::FieldKind::kKey ? "key '" : "column '")
        .append(field)
        .append("': ");
  return text.append(message);
}

}  // namespace

InputError::InputError(std::string file, std::size_t line, std::string field,
                       const std::string& message, FieldKind kind)
    : std::runtime_error(describe(file, line, field, message, kind)),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)),
      message_(message) {}

}  // namespace opf
