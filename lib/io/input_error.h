#pragma once
// The error every reader of user input (measurement logs, result files, YAML settings) throws: it
// says where the problem is (file, line, column or key) and what was expected there.

#include <cstddef>
#include <stdexcept>
#include <string>

namespace opf {

class InputError : public std::runtime_error {
 public:
  /// What `field` names: a CSV column or a YAML key path. Only changes the wording of what().
  enum class FieldKind { kColumn, kKey };

  /// `line` is 1-based, 0 for the file as a whole; `field` may be empty. what() reads
  /// `file:line: column 'field': message` (or `key 'field'`), leaving out the absent parts.
  InputError(std::string file, std::size_t line, std::string field, const std::string& message,
             FieldKind kind = FieldKind::kColumn);

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& field() const { return field_; }
  /// The message alone, without the location prefix.
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  std::size_t line_;
  std::string field_;
  std::string message_;
};

}  // namespace opf
