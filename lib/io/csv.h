#pragma once
// The small CSV dialect shared by the measurement-log and result-file readers: a header line,
// comma-separated fields, optional double quotes, tolerant of BOM, CRLF, blank lines and padding.

#include <cstddef>
#include <istream>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opf::csv {

/// Splits one line (its line end removed) into fields with surrounding spaces and tabs trimmed. A
/// field may be enclosed in double quotes; its content is then kept verbatim, "" standing for a
/// quote. Throws InputError at `source`:`line` on an unterminated quote or text after the closing
/// quote. Quoted fields cannot span lines.
std::vector<std::string> split_line(std::string_view text, const std::string& source,
                                    std::size_t line);

/// `text` as a double when the whole of it is a decimal number (std::from_chars, so independent of
/// the locale; an optional leading '+' is accepted); std::nullopt otherwise, including for a value
/// out of the range of double. "nan" and "inf" do parse: callers decide whether they are allowed.
std::optional<double> parse_double(std::string_view text);

/// The shortest text that reads back as exactly `value` (std::to_chars), e.g. "0.033333".
std::string format_double(double value);

/// A time: the shortest fixed-notation text that reads back as exactly `value`, never an exponent,
/// so that a column of times reads evenly (a whole-second stamp 1600000000 is not "1.6e+09" beside
/// "1600000000.033", nor 0.0001 s "1e-04").
std::string format_time(double value);

/// `text` as one field: quoted when it holds a comma or quote or has surrounding whitespace, so
/// that split_line gives it back unchanged.
std::string quote_if_needed(std::string_view text);

/// The longest line a Reader accepts (1 MiB, thousands of columns): a longer one is an error, not
/// an allocation of the whole file.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

/// Columns a file has all of or none of (a quaternion's four, which a log of positions leaves
/// out); with `required`, all of them.
struct ColumnGroup {
  std::vector<std::string> names;
  bool required = false;
};

/// Reads a CSV stream row by row against its header (the first non-blank line), keeping the line
/// numbers for error messages.
class Reader {
 public:
  /// Reads the header and checks it has every one of `required_columns` and all or none of
  /// `group`'s (other columns are allowed). Throws InputError when the input has no non-blank
  /// line, when columns are missing (listing them all) or when one appears more than once.
  Reader(std::istream& in, std::string source, std::span<const std::string_view> required_columns,
         const ColumnGroup& group = {});

  /// A file with no header line: `columns` names its first fields, in order. Whitespace-separated
  /// with '#' comment lines (the TUM trajectory format), or comma-separated with further fields
  /// allowed after the named ones (MOTChallenge's gt.txt and det.txt).
  struct Headerless {
    std::vector<std::string> columns;
    bool whitespace_separated = true;
    /// Lines starting with '#' are comments (always so when whitespace-separated).
    bool comments = false;
    /// Whitespace-separated: this many further fields may follow the named ones (a score).
    std::size_t optional_fields = 0;
  };
  Reader(std::istream& in, std::string source, Headerless format);

  const std::string& source() const { return source_; }
  const std::vector<std::string>& header() const { return header_; }
  /// Whether the header has column `name`.
  bool has_column(std::string_view name) const;

  /// Header index of the column `name`; throws std::out_of_range when the header lacks it (pass it
  /// as a required column to get an InputError instead).
  std::size_t column(std::string_view name) const;

  /// Moves to the next non-blank row; false at the end of the input. Throws InputError when the
  /// row has a different number of fields than the header.
  bool next();

  /// 1-based line number of the current row (of the header before the first next()).
  std::size_t line() const { return line_; }
  const std::string& field(std::size_t column) const { return fields_.at(column); }
  /// The current row's number of fields (more than the header's in a Headerless comma file).
  std::size_t fields() const { return fields_.size(); }
  /// The field as a finite number; throws InputError naming the column otherwise.
  double number(std::size_t column) const;
  /// The field as a number where nan and inf are legitimate values (as std::to_chars writes them).
  double number_or_non_finite(std::size_t column) const;

  /// Throws InputError at the current line, naming `column`'s header name.
  [[noreturn]] void fail(std::size_t column, const std::string& message) const;
  /// Throws InputError at the current line without naming a column.
  [[noreturn]] void fail(const std::string& message) const;

 private:
  /// The next non-blank line split into fields; false at the end of the input.
  bool read_line(std::vector<std::string>& fields);

  std::istream& in_;
  std::string source_;
  std::vector<std::string> header_;
  std::size_t header_line_ = 0;
  std::vector<std::string> fields_;
  std::size_t line_ = 0;
  std::size_t lines_read_ = 0;
  bool whitespace_separated_ = false;
  bool comments_ = false;            // lines starting with '#' skipped
  bool headerless_ = false;          // more fields than named are allowed when comma-separated
  std::size_t optional_fields_ = 0;  // whitespace-separated: further fields allowed
};

}  // namespace opf::csv
