#include "opf/io/log_format_detection.h"

#include "opf/io/csv.h"
#include "opf/io/input_error.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace opf {
namespace {

std::vector<std::string> whitespace_fields(std::string_view line) {
  std::istringstream in{std::string(line)};
  std::vector<std::string> fields;
  for (std::string field; in >> field;) fields.push_back(field);
  return fields;
}

// TUM: eight numbers separated by spaces or tabs.
bool eight_numbers(std::string_view line) {
  const std::vector<std::string> fields = whitespace_fields(line);
  return fields.size() == kTumColumns.size() &&
         std::all_of(fields.begin(), fields.end(),
                     [](const std::string& field) { return csv::parse_double(field).has_value(); });
}

// At least `count` numbers separated by commas: MOTChallenge's frame, id, box and more; an ASL
// CSV's timestamp, position, quaternion and more.
bool comma_separated_numbers(std::string_view line, std::size_t count) {
  std::vector<std::string> fields;
  try {
    fields = csv::split_line(line, "", 0);
  } catch (const InputError&) {
    return false;  // a stray quote: not a line of numbers
  }
  for (const std::string& field : fields)
    if (!csv::parse_double(field)) return false;
  return fields.size() >= count;
}

// KITTI tracking: frame, track id, a type word, then numbers: 17 fields, or 18 with a score.
bool kitti_row(std::string_view line) {
  const std::vector<std::string> fields = whitespace_fields(line);
  if (fields.size() != kKittiColumns.size() && fields.size() != kKittiColumns.size() + 1)
    return false;
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (csv::parse_double(fields[i]).has_value() == (i == 2)) return false;
  return true;
}

bool starts_with_hash(std::string_view line) {
  const std::size_t start = line.find_first_not_of(" \t");
  return start != std::string_view::npos && line[start] == '#';
}

}  // namespace

LogFormat detect_log_format(const std::filesystem::path& name, std::string_view first_line,
                            std::string_view first_data_line) {
  if (starts_with_hash(first_line))
    return comma_separated_numbers(first_data_line, kEurocColumns.size()) ? LogFormat::kEuroc
                                                                          : LogFormat::kTum;
  const std::filesystem::path extension = name.extension();
  if (extension == ".tum") return LogFormat::kTum;
  if (extension == ".txt" && eight_numbers(first_line)) return LogFormat::kTum;
  if (extension == ".txt" && kitti_row(first_line)) return LogFormat::kKitti;
  if (extension == ".txt" && comma_separated_numbers(first_line, kMotColumns.size()))
    return LogFormat::kMot;
  return LogFormat::kCsv;
}

LogFormat detect_log_format(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return LogFormat::kCsv;
  // The first 64 KiB hold the first line of any log; a file without line ends is not read whole.
  std::ifstream in(path, std::ios::binary);
  std::string head(std::size_t{1} << 16, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::istringstream lines(head);
  // The first non-blank line, and the first that is not a '#' comment either.
  std::string first, data;
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (first.empty()) first = line;
    if (!starts_with_hash(line)) {
      data = line;
      break;
    }
  }
  return detect_log_format(path, first, data);
}

}  // namespace opf
