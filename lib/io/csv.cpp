#include "opf/io/csv.h"

#include "opf/io/input_error.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace opf::csv {

namespace {

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

// Reads one line into `text`, without its '\n'; false at the end of the input. Returns true with
// `too_long` set as soon as the line exceeds kMaxLineBytes, so that a file with no line breaks
// (a binary file, a mangled export) is never held in memory whole. It reads the stream buffer
// directly, so a read error ends the input or propagates as the buffer's exception.
bool read_bounded_line(std::istream& in, std::string& text, bool& too_long) {
  text.clear();
  too_long = false;
  std::streambuf* const buffer = in.rdbuf();
  for (int c = buffer->sbumpc(); c != std::char_traits<char>::eof(); c = buffer->sbumpc()) {
    if (c == '\n') return true;
    if (text.size() == kMaxLineBytes) {
      too_long = true;
      return true;
    }
    text.push_back(static_cast<char>(c));
  }
  return !text.empty();  // a last line without '\n'
}

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

std::vector<std::string> split_whitespace(std::string_view text) {
  std::vector<std::string> fields;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
    if (i > start) fields.emplace_back(text.substr(start, i - start));
  }
  return fields;
}

// A control byte (other than a tab) is no text a log holds: the file is binary, and quoting its
// bytes in a message would write them to the terminal.
void refuse_control_bytes(std::string_view line, const std::string& source, std::size_t number) {
  for (std::size_t i = 0; i < line.size(); ++i) {
    const auto byte = static_cast<unsigned char>(line[i]);
    if ((byte < 0x20 && byte != '\t') || byte == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", byte);
      throw InputError(source, number, "",
                       "not a text file: control byte " + std::string(hex) + " at byte " +
                           std::to_string(i + 1) + " of the line");
    }
  }
}

std::vector<std::string> concatenated(std::vector<std::string> a,
                                      const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::string join_quoted(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "'" : ", '") + name + "'";
  return text;
}

}  // namespace

std::vector<std::string> split_line(std::string_view text, const std::string& source,
                                    std::size_t line) {
  std::vector<std::string> fields;
  std::size_t i = 0;
  while (true) {
    while (i < text.size() && is_blank(text[i])) ++i;
    std::string field;
    if (i < text.size() && text[i] == '"') {
      const std::size_t open = i++;
      bool closed = false;
      while (i < text.size() && !closed) {
        if (text[i] != '"') {
          field += text[i++];
        } else if (i + 1 < text.size() && text[i + 1] == '"') {
          field += '"';
          i += 2;
        } else {
          ++i;
          closed = true;
        }
      }
      if (!closed)
        throw InputError(source, line, "",
                         "field " + std::to_string(fields.size() + 1) +
                             ": unterminated double quote opened at character " +
                             std::to_string(open + 1));
      while (i < text.size() && is_blank(text[i])) ++i;
      if (i < text.size() && text[i] != ',')
        throw InputError(source, line, "",
                         "field " + std::to_string(fields.size() + 1) +
                             ": expected a comma after the closing quote, got '" + text[i] + "'");
    } else {
      const std::size_t comma = std::min(text.find(',', i), text.size());
      field = trim(text.substr(i, comma - i));
      i = comma;
    }
    fields.push_back(std::move(field));
    if (i >= text.size()) return fields;
    ++i;  // past the comma
  }
}

std::optional<double> parse_double(std::string_view text) {
  // from_chars rejects a leading '+', which some exporters write.
  if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
  double value = 0.0;
  const char* const end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

std::string format_double(double value) {
  char buffer[64];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  if (ec != std::errc()) throw std::logic_error("format_double: buffer too small");
  return std::string(buffer, ptr);
}

std::string format_time(double value) {
  // The shortest fixed text of a finite double has at most 309 digits before the point and 324
  // after it (a sign and the point besides).
  char buffer[1400];
  const auto [ptr, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
  if (ec != std::errc()) throw std::logic_error("format_time: buffer too small");
  return std::string(buffer, ptr);
}

std::string quote_if_needed(std::string_view text) {
  if (text.find_first_of("\r\n") != std::string_view::npos)
    throw std::invalid_argument("a CSV field cannot hold a line break: \"" + std::string(text) +
                                "\"");
  const bool needs_quotes = text.find_first_of(",\"") != std::string_view::npos ||
                            (!text.empty() && (is_blank(text.front()) || is_blank(text.back())));
  if (!needs_quotes) return std::string(text);
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

Reader::Reader(std::istream& in, std::string source,
               std::span<const std::string_view> required_columns, const ColumnGroup& group)
    : in_(in), source_(std::move(source)) {
  std::vector<std::string> required(required_columns.begin(), required_columns.end());
  const auto joined = [](const std::vector<std::string>& names) {
    std::string text;
    for (const auto& name : names) text += (text.empty() ? "" : ",") + name;
    return text;
  };
  if (!read_line(header_)) {
    const std::string optional =
        group.names.empty() || group.required ? "" : " and, all or none, " + joined(group.names);
    throw InputError(source_, 0, "",
                     "empty file: expected a header line with the columns " +
                         joined(group.required ? concatenated(required, group.names) : required) +
                         optional);
  }
  header_line_ = line_;

  const auto absent = [&](const std::vector<std::string>& names) {
    std::vector<std::string> missing;
    for (const auto& name : names) {
      const auto count = std::count(header_.begin(), header_.end(), name);
      if (count == 0) missing.push_back(name);
      if (count > 1) fail("column '" + name + "' appears more than once in the header");
    }
    return missing;
  };
  const std::vector<std::string> required_missing = absent(required);
  const std::vector<std::string> group_missing = absent(group.names);
  const bool partial_group = !group_missing.empty() && group_missing.size() < group.names.size();
  const std::vector<std::string> missing = partial_group || group.required
                                               ? concatenated(required_missing, group_missing)
                                               : required_missing;
  if (!missing.empty()) {
    // A log without a header has numbers where the names should be: say so.
    const bool none_found =
        required_missing.size() == required.size() && group_missing.size() == group.names.size();
    // A header of one field holding ';' or a tab was written with another delimiter: say which.
    std::string hint = none_found ? "; is the header line missing?" : "";
    if (header_.size() == 1 && header_[0].find(';') != std::string::npos)
      hint = "; the header is separated by ';': columns must be separated by commas";
    else if (header_.size() == 1 && header_[0].find('\t') != std::string::npos)
      hint = "; the header is separated by tabs: columns must be separated by commas";
    if (partial_group) hint += "; " + joined(group.names) + " come together: all of them or none";
    fail("missing required column" + std::string(missing.size() > 1 ? "s " : " ") +
         join_quoted(missing) + " (the header has " + join_quoted(header_) + ")" + hint);
  }
}

bool Reader::has_column(std::string_view name) const {
  return std::find(header_.begin(), header_.end(), name) != header_.end();
}

Reader::Reader(std::istream& in, std::string source, Headerless format)
    : in_(in),
      source_(std::move(source)),
      header_(std::move(format.columns)),
      whitespace_separated_(format.whitespace_separated),
      comments_(format.comments || format.whitespace_separated),
      headerless_(true),
      optional_fields_(format.optional_fields) {}

std::size_t Reader::column(std::string_view name) const {
  const auto it = std::find(header_.begin(), header_.end(), name);
  if (it == header_.end())
    throw std::out_of_range("csv::Reader: no column '" + std::string(name) + "' in " + source_);
  return static_cast<std::size_t>(it - header_.begin());
}

bool Reader::next() {
  if (!read_line(fields_)) return false;
  if (whitespace_separated_ &&
      (fields_.size() < header_.size() || fields_.size() > header_.size() + optional_fields_)) {
    std::string names;
    for (const auto& name : header_) names += (names.empty() ? "" : " ") + name;
    const std::string most =
        optional_fields_ > 0 ? " to " + std::to_string(header_.size() + optional_fields_) : "";
    fail("expected " + std::to_string(header_.size()) + most + " fields separated by spaces (" +
         names + "), got " + std::to_string(fields_.size()));
  }
  if (headerless_ && !whitespace_separated_ && fields_.size() < header_.size()) {
    std::string names;
    for (const auto& name : header_) names += (names.empty() ? "" : ", ") + name;
    fail("expected at least " + std::to_string(header_.size()) + " fields separated by commas (" +
         names + "), got " + std::to_string(fields_.size()));
  }
  if (fields_.size() != header_.size() && !headerless_)
    fail("expected " + std::to_string(header_.size()) + " fields as in the header (line " +
         std::to_string(header_line_) + "), got " + std::to_string(fields_.size()));
  return true;
}

double Reader::number(std::size_t column) const {
  const double value = number_or_non_finite(column);
  if (!std::isfinite(value))
    fail(column, "expected a finite number, got \"" + field(column) + "\"");
  return value;
}

double Reader::number_or_non_finite(std::size_t column) const {
  const auto value = parse_double(field(column));
  if (!value) fail(column, "expected a number, got \"" + field(column) + "\"");
  return *value;
}

void Reader::fail(std::size_t column, const std::string& message) const {
  throw InputError(source_, line_, header_.at(column), message);
}

void Reader::fail(const std::string& message) const {
  throw InputError(source_, line_, "", message);
}

bool Reader::read_line(std::vector<std::string>& fields) {
  std::string text;
  bool too_long = false;
  while (read_bounded_line(in_, text, too_long)) {
    ++lines_read_;
    if (too_long)
      throw InputError(source_, lines_read_, "",
                       "line longer than " + std::to_string(kMaxLineBytes) +
                           " bytes: expected a CSV text file with one row per line");
    std::string_view view = text;
    if (lines_read_ == 1 && view.starts_with(kUtf8Bom)) view.remove_prefix(kUtf8Bom.size());
    if (view.ends_with('\r')) view.remove_suffix(1);
    refuse_control_bytes(view, source_, lines_read_);
    if (trim(view).empty()) continue;
    line_ = lines_read_;
    if (comments_ && trim(view).starts_with('#')) continue;
    if (whitespace_separated_) {
      fields = split_whitespace(view);
    } else {
      fields = split_line(view, source_, line_);
    }
    return true;
  }
  return false;
}

}  // namespace opf::csv
