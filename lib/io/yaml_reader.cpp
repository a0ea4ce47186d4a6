#include "opf/io/yaml_reader.h"

#include "opf/core/closest_name.h"
#include "opf/io/csv.h"
#include "opf/io/input_error.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <system_error>
#include <utility>

namespace opf {

namespace {
constexpr std::size_t kShownCharacters = 80;
}  // namespace

// Whole when short, else its start and its length: a file of one long line read as YAML is one
// scalar, which would otherwise be echoed whole.
std::string quoted_scalar(const std::string& scalar) {
  if (scalar.size() <= kShownCharacters) return "\"" + scalar + "\"";
  return "\"" + scalar.substr(0, kShownCharacters) + "...\" (" + std::to_string(scalar.size()) +
         " characters)";
}

namespace {

constexpr auto kKey = InputError::FieldKind::kKey;

std::size_t line_of(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() || mark.line < 0 ? 0 : static_cast<std::size_t>(mark.line) + 1;
}

/// How the value reads in a message: the scalar as written (quoted), a short list of scalars as
/// written (so that a message shows which entry is wrong), or what kind of node it is.
std::string describe(const YAML::Node& node) {
  if (node.IsScalar()) return quoted_scalar(node.Scalar());
  if (node.IsMap()) return "a mapping";
  if (!node.IsSequence()) return "nothing";
  if (node.size() == 0) return "an empty list";
  constexpr std::size_t kShown = 8;
  const bool flat =
      std::all_of(node.begin(), node.end(), [](const YAML::Node& item) { return item.IsScalar(); });
  if (!flat || node.size() > kShown) return "a list of " + std::to_string(node.size()) + " entries";
  std::string text = "[";
  for (const YAML::Node& item : node)
    text +=
        (text.size() > 1 ? ", " : "") +
        (item.Scalar().size() <= kShownCharacters ? item.Scalar() : quoted_scalar(item.Scalar()));
  return text + "]";
}

std::string_view without_plus(std::string_view text) {
  if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
  return text;
}

/// A finite number in C-locale syntax, the whole text consumed; YAML's .inf and .nan are refused.
std::optional<double> to_number(std::string_view text) {
  text = without_plus(text);
  double value = 0.0;
  const char* const end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<std::size_t> to_count(std::string_view text) {
  text = without_plus(text);
  std::size_t value = 0;
  const char* const end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

}  // namespace

YamlReader YamlReader::parse(const std::string& text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    const std::size_t line = e.mark.is_null() ? 0 : static_cast<std::size_t>(e.mark.line) + 1;
    throw InputError(source, line, "", "invalid YAML: " + e.msg);
  }
  if (root.IsDefined() && !root.IsNull() && !root.IsMap())
    throw InputError(source, line_of(root), "",
                     "expected a mapping of settings at the top level, got " + describe(root));
  return YamlReader(root, "", source);
}

YamlReader::YamlReader(const YAML::Node& node, std::string key_path, std::string source)
    : key_path_(std::move(key_path)), source_(std::move(source)) {
  if (!node.IsDefined() || node.IsNull()) return;
  line_ = line_of(node);
  if (!node.IsMap())
    throw InputError(source_, line_, key_path_, "expected a mapping, got " + describe(node), kKey);
  for (const auto& pair : node) {
    const std::size_t line = line_of(pair.first);
    if (!pair.first.IsScalar())
      throw InputError(source_, line, key_path_, "expected a key name, got " + describe(pair.first),
                       kKey);
    const std::string& key = pair.first.Scalar();
    for (const auto& entry : entries_)
      if (entry.key == key)
        throw InputError(source_, line, this->key_path(key),
                         "key given twice (first on line " + std::to_string(entry.line) + ")",
                         kKey);
    entries_.push_back({key, pair.second, line, false});
  }
}

void YamlReader::record_into(YAML::Node node) {
  record_ = node;
  recording_ = true;
}

void YamlReader::record(std::string_view key, double value) {
  if (recording_) record_[std::string(key)] = csv::format_double(value);
}

void YamlReader::record(std::string_view key, std::size_t value) {
  if (recording_) record_[std::string(key)] = value;
}

void YamlReader::record(std::string_view key, bool value) {
  if (recording_) record_[std::string(key)] = value;
}

void YamlReader::record(std::string_view key, const std::string& value) {
  if (recording_) record_[std::string(key)] = value;
}

void YamlReader::record(std::string_view key, const std::vector<double>& values) {
  if (!recording_) return;
  std::vector<std::string> texts;
  for (const double v : values) texts.push_back(csv::format_double(v));
  record(key, texts);
}

void YamlReader::record(std::string_view key, const std::vector<std::string>& values) {
  if (!recording_ || values.empty()) return;  // an optional value not set
  YAML::Node list(YAML::NodeType::Sequence);
  for (const std::string& v : values) list.push_back(v);
  list.SetStyle(YAML::EmitterStyle::Flow);
  record_[std::string(key)] = list;
}

void YamlReader::get(std::string_view key, double& out) {
  const Entry* entry = find(key);
  if (entry == nullptr) {
    record(key, out);
    return;
  }
  const auto value = to_number(scalar(*entry, "a number"));
  if (!value) fail(key, "expected a finite number, got " + describe(entry->value));
  out = *value;
  record(key, out);
}

void YamlReader::get(std::string_view key, std::size_t& out) {
  const Entry* entry = find(key);
  if (entry == nullptr) {
    record(key, out);
    return;
  }
  const auto value = to_count(scalar(*entry, "a non-negative integer"));
  if (!value) fail(key, "expected a non-negative integer, got " + describe(entry->value));
  out = *value;
  record(key, out);
}

void YamlReader::get(std::string_view key, std::vector<double>& out, std::size_t size) {
  const Entry* entry = find(key);
  if (entry == nullptr) {
    record(key, out);
    return;
  }
  const std::string expectation = "a sequence of " + std::to_string(size) + " numbers";
  if (!entry->value.IsSequence() || entry->value.size() != size)
    fail(key, "expected " + expectation + ", got " + describe(entry->value));
  std::vector<double> values;
  for (const YAML::Node& item : entry->value) {
    const auto value = item.IsScalar() ? to_number(item.Scalar()) : std::nullopt;
    if (!value) fail(key, "expected " + expectation + ", got " + describe(entry->value));
    values.push_back(*value);
  }
  out = std::move(values);
  record(key, out);
}

void YamlReader::get(std::string_view key, bool& out) {
  const Entry* entry = find(key);
  if (entry == nullptr) {
    record(key, out);
    return;
  }
  scalar(*entry, "true or false");
  bool value = false;
  if (!YAML::convert<bool>::decode(entry->value, value))
    fail(key, "expected true or false, got " + describe(entry->value));
  out = value;
  record(key, out);
}

void YamlReader::get(std::string_view key, std::string& out) {
  const Entry* entry = find(key);
  if (entry == nullptr) {
    record(key, out);
    return;
  }
  out = scalar(*entry, "a string");
  record(key, out);
}

void YamlReader::get(std::string_view key, std::vector<std::string>& out) {
  const Entry* entry = find(key);
  if (entry == nullptr) {
    record(key, out);
    return;
  }
  const std::string expectation = "a list of names or values";
  if (entry->value.IsScalar()) {
    out = {entry->value.Scalar()};
    record(key, out);
    return;
  }
  if (!entry->value.IsSequence() || entry->value.size() == 0)
    fail(key, "expected " + expectation + ", got " + describe(entry->value));
  std::vector<std::string> values;
  for (const YAML::Node& item : entry->value) {
    if (!item.IsScalar())
      throw InputError(source_, line_of(item), key_path(key),
                       "expected " + expectation + ", got " + describe(item) + " in the list",
                       kKey);
    values.push_back(item.Scalar());
  }
  out = std::move(values);
  record(key, out);
}

std::vector<YamlReader::Item> YamlReader::items(std::string_view key) {
  std::vector<Item> result;
  const Entry* entry = find(key);
  if (entry == nullptr || entry->value.IsNull()) return result;
  if (!entry->value.IsMap()) fail(key, "expected a mapping, got " + describe(entry->value));
  for (const auto& pair : entry->value)
    result.push_back({pair.first.Scalar(), pair.second, line_of(pair.first)});
  return result;
}

void YamlReader::get_positive(std::string_view key, double& out) {
  const Entry* entry = find(key);
  if (entry == nullptr) {
    record(key, out);
    return;
  }
  const auto value = to_number(scalar(*entry, "a positive number"));
  if (!value || !(*value > 0.0))
    fail(key, "expected a positive number, got " + describe(entry->value));
  out = *value;
  record(key, out);
}

void YamlReader::get_positive(std::string_view key, std::size_t& out) {
  const Entry* entry = find(key);
  if (entry == nullptr) {
    record(key, out);
    return;
  }
  const auto value = to_count(scalar(*entry, "a positive integer"));
  if (!value || *value < 1) fail(key, "expected a positive integer, got " + describe(entry->value));
  out = *value;
  record(key, out);
}

void YamlReader::require(std::string_view key, bool ok, const std::string& expectation) const {
  const Entry* entry = peek(key);
  if (entry != nullptr && !ok)
    fail(key, "expected " + expectation + ", got " + describe(entry->value));
}

YamlReader& YamlReader::child(std::string_view key) {
  const std::string path = key_path(key);
  for (const auto& existing : children_)
    if (existing->key_path_ == path) return *existing;
  const Entry* entry = find(key);
  children_.push_back(
      std::make_unique<YamlReader>(entry ? entry->value : YAML::Node(), path, source_));
  if (recording_) {
    record_[std::string(key)] = YAML::Node(YAML::NodeType::Map);
    children_.back()->record_into(record_[std::string(key)]);
  }
  return *children_.back();
}

std::vector<YamlReader*> YamlReader::sequence(std::string_view key) {
  std::vector<YamlReader*> items;
  const Entry* entry = find(key);
  if (entry == nullptr || entry->value.IsNull()) return items;
  if (!entry->value.IsSequence()) fail(key, "expected a list, got " + describe(entry->value));
  std::size_t index = 0;
  for (const YAML::Node& item : entry->value) {
    const std::string path = key_path(key).append("[").append(std::to_string(index++)).append("]");
    if (!item.IsMap())
      throw InputError(source_, line_of(item), path, "expected a mapping, got " + describe(item),
                       kKey);
    children_.push_back(std::make_unique<YamlReader>(item, path, source_));
    items.push_back(children_.back().get());
  }
  return items;
}

void YamlReader::finish() const {
  for (const auto& entry : entries_) {
    if (entry.read) continue;
    std::string message = "unknown key";
    // Only a near miss is worth suggesting; otherwise list what would have been understood.
    if (const auto closest = closest_name(entry.key, known_keys_)) {
      message += "; did you mean '" + *closest + "'?";
    } else if (!known_keys_.empty()) {
      message += "; expected one of ";
      for (const auto& known : known_keys_)
        message.append(&known == &known_keys_.front() ? "'" : ", '").append(known).append("'");
    }
    throw InputError(source_, entry.line, key_path(entry.key), message, kKey);
  }
  for (const auto& child : children_) child->finish();
}

void YamlReader::fail(std::string_view key, const std::string& message) const {
  const Entry* entry = peek(key);
  throw InputError(source_, entry ? entry->line : line_, key_path(key), message, kKey);
}

std::string YamlReader::key_path(std::string_view key) const {
  return key_path_.empty() ? std::string(key) : key_path_ + "." + std::string(key);
}

const YamlReader::Entry* YamlReader::find(std::string_view key) {
  if (std::find(known_keys_.begin(), known_keys_.end(), key) == known_keys_.end())
    known_keys_.emplace_back(key);
  for (auto& entry : entries_) {
    if (entry.key == key) {
      entry.read = true;
      return &entry;
    }
  }
  return nullptr;
}

const YamlReader::Entry* YamlReader::peek(std::string_view key) const {
  for (const auto& entry : entries_)
    if (entry.key == key) return &entry;
  return nullptr;
}

std::string YamlReader::scalar(const Entry& entry, const std::string& expectation) const {
  if (!entry.value.IsScalar())
    fail(entry.key, "expected " + expectation + ", got " + describe(entry.value));
  return entry.value.Scalar();
}

}  // namespace opf
