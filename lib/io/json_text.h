#pragma once
// The few JSON texts the result files need beyond numbers: quoted strings and a YAML tree (the
// effective settings) as a JSON value, so a result file can carry the settings it was made with.

#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>

namespace opf {

/// `text` as a JSON string literal, quotes and control characters escaped.
std::string json_string(std::string_view text);

/// `node` as JSON: mappings as objects (in order), sequences as arrays, scalars as numbers when
/// they are finite decimal numbers, as true/false when booleans, as strings otherwise. Nested
/// lines are indented by `indent` spaces more than the first.
std::string yaml_as_json(const YAML::Node& node, std::size_t indent = 0);

}  // namespace opf
