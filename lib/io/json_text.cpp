#include "opf/io/json_text.h"

#include "opf/io/csv.h"

#include <cmath>
#include <cstdio>

namespace opf {

std::string json_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
          out += escaped;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string yaml_as_json(const YAML::Node& node, std::size_t indent) {
  const std::string inner(indent + 2, ' ');
  const std::string outer(indent, ' ');
  if (node.IsMap()) {
    if (node.size() == 0) return "{}";
    std::string out = "{\n";
    bool first = true;
    for (const auto& pair : node) {
      out += (first ? "" : ",\n") + inner + json_string(pair.first.Scalar()) + ": " +
             yaml_as_json(pair.second, indent + 2);
      first = false;
    }
    return out + "\n" + outer + "}";
  }
  if (node.IsSequence()) {
    std::string out = "[";
    bool first = true;
    for (const auto& item : node) {
      out += (first ? "" : ", ") + yaml_as_json(item, indent + 2);
      first = false;
    }
    return out + "]";
  }
  if (!node.IsScalar()) return "null";
  const std::string& text = node.Scalar();
  // JSON numbers have no leading '+' or '.' and no trailing '.'.
  const bool json_number_form = !text.empty() && text.front() != '+' && text.front() != '.' &&
                                text.back() != '.' && text.find("-.") == std::string::npos;
  if (const auto number = csv::parse_double(text);
      json_number_form && number && std::isfinite(*number))
    return text;
  if (text == "true" || text == "false") return text;
  return json_string(text);
}

}  // namespace opf
