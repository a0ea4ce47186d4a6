#pragma once
// Reads a settings file's mapping into an options struct by walking its description
// (core/option_schema.h): each key present is parsed and checked against the field's Bounds, and
// an error names the file, the line and the key path. The ranges are those validate() enforces,
// from the same description.

#include "opf/core/option_schema.h"
#include "opf/io/yaml_reader.h"

#include <Eigen/Core>

#include <algorithm>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace opf {

class YamlOptionReader {
 public:
  explicit YamlOptionReader(YamlReader& yaml) : stack_{&yaml} {}

  void number(std::string_view key, double& out, const Bounds& bounds) {
    yaml().get(key, out);
    yaml().require(key, bounds.admits(out), std::string(bounds.expectation));
  }
  void integer(std::string_view key, std::size_t& out, const Bounds& bounds) {
    yaml().get(key, out);
    yaml().require(key, bounds.admits(static_cast<double>(out)), std::string(bounds.expectation));
  }
  void integer(std::string_view key, int& out, const Bounds& bounds) {
    std::size_t value = static_cast<std::size_t>(out);
    integer(key, value, bounds);
    out = static_cast<int>(value);
  }
  void flag(std::string_view key, bool& out) { yaml().get(key, out); }
  template <class Enum, std::size_t N>
  void choice(std::string_view key, const EnumNames<Enum, N>& names, Enum& out) {
    yaml().get(key, names, out);
  }
  /// A non-empty list of distinct names from the table, e.g. `models: [position, velocity]`.
  template <class Enum, std::size_t N>
  void choices(std::string_view key, const EnumNames<Enum, N>& names, std::vector<Enum>& out) {
    std::vector<std::string> words;
    for (const Enum value : out) words.emplace_back(name_of(names, value));
    yaml().get(key, words);
    // One expectation for an unknown name and a repeated one: the message shows the list.
    const std::string expectation = "a list of distinct names, each " + name_list(names);
    std::vector<Enum> values;
    for (const std::string& word : words) {
      const auto value = parse_name(names, word);
      yaml().require(key, value && std::find(values.begin(), values.end(), *value) == values.end(),
                     expectation);
      values.push_back(*value);
    }
    out = std::move(values);
  }
  void numbers(std::string_view key, std::vector<double>& out, const Bounds& bounds);
  void vector3(std::string_view key, Eigen::Vector3d& out);
  /// [x, y, z] or [x, y, z, w] (core/homogeneous_point.h); a point is written back as three.
  void optional_point(std::string_view key, std::optional<Eigen::Vector4d>& out);
  template <class Describe>
  void section(std::string_view key, Describe&& describe) {
    stack_.push_back(&yaml().child(key));
    describe();
    stack_.pop_back();
  }

 private:
  YamlReader& yaml() { return *stack_.back(); }
  std::vector<YamlReader*> stack_;
};

}  // namespace opf
