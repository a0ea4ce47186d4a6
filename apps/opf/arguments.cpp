#include "arguments.h"

#include "opf/core/closest_name.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace opf::cli {
namespace {

std::string unknown_option(const std::string& name, const std::vector<OptionSpec>& specs) {
  std::vector<std::string> names;
  for (const auto& s : specs) names.push_back(s.name);
  std::string message = "unknown option '--" + name + "'";
  if (const auto closest = closest_name(name, names))
    message += "; did you mean '--" + *closest + "'?";
  return message;
}

}  // namespace

Arguments::Arguments(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      help_ = true;
      continue;
    }
    if (arg.rfind("--", 0) != 0) throw UsageError{"unexpected argument '" + arg + "'"};
    std::string name = arg.substr(2);
    std::optional<std::string> inline_value;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      inline_value = name.substr(eq + 1);
      name.resize(eq);
    }
    const OptionSpec* spec = nullptr;
    for (const auto& s : specs)
      if (s.name == name) spec = &s;
    if (!spec) throw UsageError{unknown_option(name, specs)};
    if (has(name)) throw UsageError{"option '--" + name + "' given twice"};
    if (spec->value_name.empty()) {
      if (inline_value) throw UsageError{"option '--" + name + "' takes no value"};
      values_.emplace_back(name, "");
      continue;
    }
    if (inline_value) {
      values_.emplace_back(name, *inline_value);
    } else {
      if (i + 1 >= args.size()) throw UsageError{"option '--" + name + "' needs a value"};
      values_.emplace_back(name, args[++i]);
    }
  }
}

bool Arguments::has(const std::string& name) const {
  return get(name).has_value();
}

std::optional<std::string> Arguments::get(const std::string& name) const {
  for (const auto& [key, value] : values_)
    if (key == name) return value;
  return std::nullopt;
}

std::string Arguments::require(const std::string& name) const {
  auto value = get(name);
  if (!value) throw UsageError{"option '--" + name + "' is required"};
  return *value;
}

std::optional<unsigned long long> Arguments::get_count(const std::string& name) const {
  const auto text = get(name);
  if (!text) return std::nullopt;
  unsigned long long value = 0;
  const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (error != std::errc() || end != text->data() + text->size())
    throw UsageError{"option '--" + name + "' expects a non-negative integer, got '" + *text + "'"};
  return value;
}

std::optional<double> Arguments::get_number(const std::string& name) const {
  const auto text = get(name);
  if (!text) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (error != std::errc() || end != text->data() + text->size() || !std::isfinite(value))
    throw UsageError{"option '--" + name + "' expects a number, got '" + *text + "'"};
  return value;
}

SplitCommandLine split_positional(const std::vector<std::string>& raw,
                                  const std::vector<OptionSpec>& specs) {
  const auto is_switch = [&](const std::string& option) {
    for (const OptionSpec& spec : specs)
      if ("--" + spec.name == option) return spec.value_name.empty();
    return false;
  };
  SplitCommandLine split;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const bool help = raw[i] == "--help" || raw[i] == "-h";
    if (help || raw[i].rfind("--", 0) == 0) {
      split.options.push_back(raw[i]);
      if (!help && !is_switch(raw[i]) && raw[i].find('=') == std::string::npos &&
          i + 1 < raw.size())
        split.options.push_back(raw[++i]);
    } else {
      split.positional.push_back(raw[i]);
    }
  }
  return split;
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

std::string usage(const std::string& command, const std::string& summary,
                  const std::vector<OptionSpec>& specs) {
  std::ostringstream out;
  out << "Usage: opf " << command << " [options]\n\n" << summary << "\n\nOptions:\n";
  for (const auto& spec : specs) {
    std::string left = "  --" + spec.name + (spec.value_name.empty() ? "" : " " + spec.value_name);
    if (left.size() < 26) left.resize(26, ' ');
    out << left << " " << spec.help << "\n";
  }
  out << "  --help                   show this help\n";
  return out.str();
}

}  // namespace opf::cli
