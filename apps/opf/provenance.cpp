#include "provenance.h"

#include "cli/version.h"
#include "opf/io/estimator_settings_yaml.h"
#include "opf/io/json_text.h"

#include <sstream>

namespace opf::cli {
namespace {

std::string shell_quoted(const std::string& arg) {
  const bool plain = !arg.empty() && arg.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789-_./=,:+@%") == std::string::npos;
  if (plain) return arg;
  std::ostringstream quoted;
  quoted << '\'';
  for (const char c : arg) {
    if (c == '\'')
      quoted << "'\\''";
    else
      quoted << c;
  }
  quoted << '\'';
  return quoted.str();
}

std::string settings_json(const EstimatorSettings& settings, std::size_t indent) {
  return yaml_as_json(estimator_settings_node(settings), indent);
}

}  // namespace

std::string command_line(const std::string& subcommand, const std::vector<std::string>& args) {
  std::ostringstream line;
  line << "opf " << subcommand;
  for (const std::string& arg : args) line << ' ' << shell_quoted(arg);
  return line.str();
}

std::string provenance_json(const std::string& command,
                            const std::vector<std::pair<std::string, EstimatorSettings>>& settings,
                            std::size_t indent) {
  const std::string inner(indent + 2, ' ');
  std::ostringstream out;
  out << "{\n"
      << inner << "\"version\": " << json_string(OPF_VERSION) << ",\n"
      << inner << "\"commit\": " << json_string(OPF_COMMIT) << ",\n"
      << inner << "\"command\": " << json_string(command) << ",\n"
      << inner << "\"settings\": ";
  if (settings.size() == 1 && settings.front().first.empty()) {
    out << settings_json(settings.front().second, indent + 2);
  } else {
    out << "{\n";
    for (std::size_t i = 0; i < settings.size(); ++i)
      out << inner << "  " << json_string(settings[i].first) << ": "
          << settings_json(settings[i].second, indent + 4)
          << (i + 1 < settings.size() ? ",\n" : "\n");
    out << inner << "}";
  }
  out << "\n" << std::string(indent, ' ') << "}";
  return out.str();
}

}  // namespace opf::cli
