#pragma once
// Reads a YAML mapping into an options struct with precise errors: wrong types, out-of-range values
// and misspelt keys are reported with the full key path, the line and a suggestion.

#include "opf/core/enum_names.h"

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace opf {

/// A scalar as an error message quotes it: in double quotes, whole up to 80 characters, else its
/// first 80 and its length.
std::string quoted_scalar(const std::string& scalar);

/// Usage: read every key the struct knows with get() (only keys present in the file are
/// assigned, so defaults stay), descend with child(), then call finish() on the top-level reader to
/// reject the keys nobody read. Every error is an InputError naming `source`, the line and the key
/// path, e.g. `pf.resampling.scheme`.
class YamlReader {
 public:
  /// Parses a document whose top level is a mapping; an empty document is an empty mapping.
  /// Throws InputError with the line on a YAML syntax error or another kind of top level.
  static YamlReader parse(const std::string& text, const std::string& source);

  /// Wraps `node`, found at `key_path` ("" for the top level) of `source`. A null node reads as an
  /// empty mapping; any other non-mapping, or a key given twice, throws InputError.
  YamlReader(const YAML::Node& node, std::string key_path, std::string source);

  /// Assigns `out` when `key` is present. Throws InputError when the value is not of the type:
  /// a finite number, a non-negative integer, a boolean (true/false, yes/no, on/off), a scalar.
  void get(std::string_view key, double& out);
  void get(std::string_view key, std::size_t& out);
  void get(std::string_view key, bool& out);
  void get(std::string_view key, std::string& out);
  /// An enum spelled by its table's words (core/enum_names.h); `out`'s word is the default, and
  /// any other word fails with "expected a, b or c, got "word"".
  template <class Enum, std::size_t N>
  void get(std::string_view key, const EnumNames<Enum, N>& names, Enum& out) {
    std::string word(name_of(names, out));
    get(key, word);
    if (const auto value = parse_name(names, word))
      out = *value;
    else
      fail(key, "expected " + name_list(names) + ", got \"" + word + "\"");
  }
  /// A sequence of exactly `size` finite numbers, e.g. `camera_position: [0.55, 0, 0.49]`.
  void get(std::string_view key, std::vector<double>& out, std::size_t size);

  /// A non-empty list of scalars, e.g. `estimators: [opf, pf]`; a single scalar reads as a list
  /// of one. InputError for mappings, nested lists and empty lists.
  void get(std::string_view key, std::vector<std::string>& out);

  /// One entry of a mapping whose keys are data rather than options (a sweep's parameter grid).
  struct Item {
    std::string key;
    YAML::Node value;
    std::size_t line = 0;  ///< 1-based line of the key
  };
  /// The entries of the mapping at `key` in file order (none when absent); they all count as
  /// read, whatever their keys. InputError when `key` holds something else.
  std::vector<Item> items(std::string_view key);

  /// The file (or other source) this reader's errors name.
  const std::string& source() const { return source_; }

  /// get() that also requires out > 0 (for counts: out >= 1).
  void get_positive(std::string_view key, double& out);
  void get_positive(std::string_view key, std::size_t& out);

  /// For checks get() cannot express: when `key` is present and `ok` is false, throws InputError
  /// "expected <expectation>, got <the value as written>".
  void require(std::string_view key, bool ok, const std::string& expectation) const;

  /// Whether the mapping has `key` (without marking it read).
  bool has_key(std::string_view key) const { return peek(key) != nullptr; }
  /// The nested mapping at `key` (an empty one when absent). Owned by this reader, which checks it
  /// in finish().
  YamlReader& child(std::string_view key);
  /// The mappings of the sequence at `key` (none when absent), each checked in finish() like a
  /// child; their paths read `key[i]`. InputError when `key` holds something else.
  std::vector<YamlReader*> sequence(std::string_view key);

  /// From now on every get() also writes the key's final value (the file's, or the default it
  /// left) into `node`, and every child() a nested mapping: reading an empty document this way
  /// records every setting the reader knows, with its value (the effective settings, dumped).
  void record_into(YAML::Node node);

  /// Throws InputError for the first key present in the file but never read here or in a child,
  /// suggesting the closest known key by edit distance ("did you mean 'scheme'?").
  void finish() const;

  /// Throws InputError at `key`'s line (the mapping's when absent) naming its full path.
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;

  /// `key` prefixed with this mapping's path: "pf.resampling" + "scheme" -> "pf.resampling.scheme".
  std::string key_path(std::string_view key) const;

 private:
  struct Entry {
    std::string key;
    YAML::Node value;
    std::size_t line = 0;  ///< 1-based line of the key
    bool read = false;
  };

  /// The entry of `key` (marked read), or nullptr when absent; `key` becomes a known key either
  /// way.
  const Entry* find(std::string_view key);
  const Entry* peek(std::string_view key) const;
  /// The scalar text of a present key, InputError when it is a mapping, sequence or null.
  std::string scalar(const Entry& entry, const std::string& expectation) const;

  void record(std::string_view key, double value);
  void record(std::string_view key, std::size_t value);
  void record(std::string_view key, bool value);
  void record(std::string_view key, const std::string& value);
  void record(std::string_view key, const std::vector<double>& values);
  void record(std::string_view key, const std::vector<std::string>& values);

  bool recording_ = false;
  YAML::Node record_;
  std::string key_path_;
  std::string source_;
  std::size_t line_ = 0;  ///< of the mapping itself; 0 when absent from the file
  std::vector<Entry> entries_;
  std::vector<std::string> known_keys_;
  std::vector<std::unique_ptr<YamlReader>> children_;
};

}  // namespace opf
