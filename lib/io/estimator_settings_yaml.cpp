#include "opf/io/estimator_settings_yaml.h"

#include "opf/io/input_error.h"
#include "opf/io/input_file.h"
#include "opf/io/yaml_option_reader.h"
#include "opf/io/yaml_reader.h"

#include <fstream>
#include <sstream>

namespace opf {

namespace {

void read_settings(YamlReader& yaml, EstimatorSettings& settings) {
  YamlOptionReader reader(yaml);
  describe_options(reader, settings);
  yaml.finish();
}

}  // namespace

EstimatorSettings parse_estimator_settings(const std::string& yaml_text,
                                           const std::string& source_name,
                                           const EstimatorSettings& base) {
  EstimatorSettings settings = base;
  YamlReader yaml = YamlReader::parse(yaml_text, source_name);
  read_settings(yaml, settings);
  return settings;
}

YAML::Node estimator_settings_node(const EstimatorSettings& settings) {
  // Reading nothing over `settings` while recording walks the whole description with each value,
  // so the dump cannot miss an option the reader knows.
  YAML::Node root(YAML::NodeType::Map);
  YamlReader yaml = YamlReader::parse("", "the effective settings");
  yaml.record_into(root);
  EstimatorSettings copy = settings;
  read_settings(yaml, copy);
  return root;
}

std::string dump_estimator_settings(const EstimatorSettings& settings) {
  YAML::Emitter out;
  out << estimator_settings_node(settings);
  return std::string(out.c_str()) + "\n";
}

EstimatorSettings load_estimator_settings(const std::filesystem::path& path,
                                          const EstimatorSettings& base) {
  std::ifstream in = open_input_file(path, "settings file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path.string(), 0, "", "read error");
  return parse_estimator_settings(text.str(), path.string(), base);
}

}  // namespace opf
