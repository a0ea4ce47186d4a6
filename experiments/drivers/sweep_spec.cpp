#include "drivers/sweep_spec.h"

#include "drivers/data_directory.h"

#include "opf/estimators/estimator_names.h"
#include "opf/io/estimator_settings_yaml.h"
#include "opf/io/input_error.h"
#include "opf/io/input_file.h"
#include "opf/io/yaml_reader.h"
#include "opf/particles/particle_filter_options.h"
#include "opf/sim/experiment_config.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace opf::experiments {
namespace {

constexpr auto kKey = InputError::FieldKind::kKey;

// A path a sweep file names: absolute, or relative to the sweep file's folder.
std::filesystem::path beside(const std::filesystem::path& sweep_file,
                             const std::filesystem::path& path) {
  return path.is_absolute() ? path : sweep_file.parent_path() / path;
}

// A bare name is a bundled experiment (experiments/<name>.yaml); anything with a slash or a
// .yaml suffix is a path relative to the sweep file.
std::filesystem::path resolve_experiment(const std::string& entry,
                                         const std::filesystem::path& sweep_file) {
  const bool is_path =
      entry.find('/') != std::string::npos || std::filesystem::path(entry).extension() == ".yaml";
  if (!is_path) return bundled_experiments() / (entry + ".yaml");
  return beside(sweep_file, entry);
}

std::string scalar_text(const YAML::Node& node, const std::string& source, std::size_t line,
                        const std::string& key) {
  if (!node.IsScalar())
    throw InputError(source, line, key, "expected a single value (a number, true/false or a name)",
                     kKey);
  return node.Scalar();
}

std::vector<std::string> split_path(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream stream(key);
  for (std::string part; std::getline(stream, part, '.');) parts.push_back(part);
  return parts;
}

// A setting's key: option names joined by dots, none empty (`opf..kappa` and "" name nothing).
void require_key_path(const std::string& key, const std::string& source, std::size_t line,
                      const std::string& where) {
  const std::vector<std::string> parts = split_path(key);
  const bool whole = !key.empty() && key.back() != '.' &&
                     std::none_of(parts.begin(), parts.end(),
                                  [](const std::string& part) { return part.empty(); });
  if (!whole)
    throw InputError(source, line, where,
                     "expected an option's key path, names joined by dots (e.g. "
                     "opf.uncertainty.kappa), got " +
                         quoted_scalar(key),
                     kKey);
}

// A sweep's or a variant's name is a folder of the results: "." and ".." would name another.
bool folder_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
}
constexpr const char* kFolderName = "a name without slashes, other than . and ..";

// Each grid point's runs go to a folder of its own: values that differ only where the folder
// name writes '_' would share one, and the second would find the first's results done.
void refuse_shared_folders(const SweepSpec& spec,
                           const std::vector<std::vector<SweepSetting>>& points) {
  std::map<std::string, std::vector<SweepSetting>> seen;
  for (const auto& point : points) {
    const auto [at, fresh] = seen.emplace(point_folder(point), point);
    if (fresh) continue;
    for (std::size_t i = 0; i < point.size(); ++i)
      if (point[i].value != at->second[i].value)
        throw InputError(spec.file.string(), point[i].line, "parameters." + point[i].key,
                         "values " + quoted_scalar(at->second[i].value) + " and " +
                             quoted_scalar(point[i].value) + " name one results folder ('" +
                             at->first + "'): '/' and whitespace are written as '_'",
                         kKey);
  }
}

// Checks one combination of settings with the estimator settings reader; its errors name the
// generated text, so they are re-anchored at the sweep file's line of the offending key.
void check_settings(const SweepSpec& spec, const std::vector<SweepSetting>& settings) {
  for (const SweepSetting& s : settings) {
    if (s.key != kParticlesKey) continue;
    std::size_t count = 0;
    std::istringstream in(s.value);
    if (!(in >> count) || !in.eof() || count == 0 || count > kMaxParticlesPerPortion)
      throw InputError(spec.file.string(), s.line, s.key,
                       "expected a positive integer below 2^31, got \"" + s.value + "\"", kKey);
  }
  try {
    parse_estimator_settings(settings_yaml(spec, settings), spec.file.string());
  } catch (const InputError& e) {
    for (const SweepSetting& s : settings)
      if (s.key == e.field() || e.field().rfind(s.key + ".", 0) == 0 ||
          s.key.rfind(e.field() + ".", 0) == 0)
        throw InputError(spec.file.string(), s.line, s.key, e.message(), kKey);
    throw InputError(spec.file.string(), 0, e.field(), e.message(), kKey);
  }
}

// Expanding and checking the runs holds them all in memory: a grid of ten parameters of ten
// values each is 10^10 runs, which would exhaust the memory before any error.
void refuse_oversized(const SweepSpec& spec) {
  std::size_t runs = spec.experiments.size() * spec.estimators.size() * spec.variants.size();
  const auto times = [&runs](std::size_t factor) {
    runs = factor != 0 && runs > kMaxRuns / factor ? kMaxRuns + 1 : runs * factor;
  };
  for (const SweepParameter& parameter : spec.parameters) times(parameter.values.size());
  times(spec.seeds);
  if (runs > kMaxRuns)
    throw InputError(spec.file.string(), 0, "",
                     "more than " + std::to_string(kMaxRuns) +
                         " runs (experiments x estimators x variants x grid points x seeds): "
                         "split the sweep into several files");
}

// A value as written in the sweep file, read again as YAML (so that "[a, b]" sets a list).
YAML::Node value_node(const SweepSpec& spec, const SweepSetting& setting) {
  try {
    return YAML::Load(setting.value);
  } catch (const YAML::Exception& e) {
    throw InputError(spec.file.string(), setting.line, setting.key,
                     "expected a value YAML reads on its own (a number, a name, or a list in "
                     "quotes such as \"[a, b]\"), got " +
                         quoted_scalar(setting.value) + ": " + e.msg,
                     kKey);
  }
}

}  // namespace

std::string point_folder(const std::vector<SweepSetting>& point) {
  std::string folder;
  for (const SweepSetting& s : point) {
    std::string value = s.value;
    std::replace_if(
        value.begin(), value.end(), [](char c) { return c == '/' || c == ' ' || c == '\t'; }, '_');
    folder += (folder.empty() ? "" : ",") + s.key + "=" + value;
  }
  return folder;
}

std::string settings_yaml(const SweepSpec& spec, const std::vector<SweepSetting>& settings) {
  YAML::Node root = spec.config ? YAML::LoadFile(spec.config->string()) : YAML::Node();
  if (!root.IsMap()) root = YAML::Node(YAML::NodeType::Map);
  for (const SweepSetting& s : settings) {
    if (s.key == kParticlesKey) continue;
    const std::vector<std::string> parts = split_path(s.key);
    std::vector<YAML::Node> chain{root};
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      YAML::Node next = chain.back()[parts[i]];
      if (!next.IsMap()) next = YAML::Node(YAML::NodeType::Map);
      chain.back()[parts[i]] = next;
      chain.push_back(next);
    }
    chain.back()[parts.back()] = value_node(spec, s);
  }
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

std::vector<std::vector<SweepSetting>> grid_points(const SweepSpec& spec) {
  std::vector<std::vector<SweepSetting>> points{{}};
  for (const SweepParameter& parameter : spec.parameters) {
    std::vector<std::vector<SweepSetting>> next;
    for (const auto& point : points)
      for (const std::string& value : parameter.values) {
        next.push_back(point);
        next.back().push_back({parameter.key, value, parameter.line});
      }
    points = std::move(next);
  }
  return points;
}

namespace {

/// The experiment files (a bare name is experiments/<name>.yaml), each loaded to check it; the
/// frame count of each by the name its results folder takes.
std::map<std::string, int> read_experiments(YamlReader& reader,
                                            const std::vector<std::string>& experiments,
                                            SweepSpec& spec) {
  std::map<std::string, int> experiment_frames;
  for (const std::string& entry : experiments) {
    const std::filesystem::path path = resolve_experiment(entry, spec.file);
    if (!names_regular_file(path))
      reader.fail("experiments", "no experiment file " + path.string() + " for '" + entry +
                                     "' (a bare name is experiments/<name>.yaml, a path is "
                                     "relative to the sweep file)");
    const int frames = sim::load_experiment(path).frames;  // its own errors name its lines
    if (!experiment_frames.emplace(path.stem().string(), frames).second)
      reader.fail("experiments", "two experiments named '" + path.stem().string() +
                                     "': their runs would share one results folder");
    spec.experiments.push_back(path);
  }
  return experiment_frames;
}

/// Every estimator registered, none twice.
void check_estimators(YamlReader& reader, const std::vector<std::string>& estimators) {
  const std::vector<std::string> known = estimator_names();
  for (const std::string& name : estimators)
    if (std::find(known.begin(), known.end(), name) == known.end())
      reader.fail("estimators", unknown_estimator_message(name));
  for (std::size_t i = 0; i < estimators.size(); ++i)
    if (std::find(estimators.begin(), estimators.begin() + i, estimators[i]) !=
        estimators.begin() + i)
      reader.fail("estimators", "estimator '" + estimators[i] + "' appears twice");
}

/// seeds, seed, particles and frames (at most every experiment's own count).
void read_run_size(YamlReader& reader, const std::map<std::string, int>& experiment_frames,
                   SweepSpec& spec) {
  reader.get_positive("seeds", spec.seeds);
  std::size_t base_seed = spec.seed;
  reader.get("seed", base_seed);
  spec.seed = base_seed;
  if (reader.has_key("particles")) {
    std::size_t particles = 0;
    reader.get_positive("particles", particles);
    reader.require("particles", particles <= kMaxParticlesPerPortion,
                   "a particle count below 2^31");
    spec.particles = particles;
  }
  if (reader.has_key("frames")) {
    std::size_t frames = 0;
    reader.get_positive("frames", frames);
    for (const auto& [experiment, count] : experiment_frames)
      if (frames > static_cast<std::size_t>(count))
        reader.fail("frames", "expected at most " + std::to_string(count) + " frames: '" +
                                  experiment + "' has " + std::to_string(count));
    spec.frames = frames;
  }
}

/// The estimator settings file (relative to the sweep file), loaded to check it; none: empty.
std::optional<std::filesystem::path> read_config(YamlReader& reader,
                                                 const std::filesystem::path& file) {
  if (!reader.has_key("config")) return std::nullopt;
  std::string config;
  reader.get("config", config);
  const std::filesystem::path path = beside(file, config);
  if (!names_regular_file(path))
    reader.fail("config", "no estimator settings file " + path.string());
  load_estimator_settings(path);  // its own errors name its lines
  return path;
}

/// The variants, each named (a folder name no other variant has) with its settings; none: one
/// variant, `default`, of no settings.
std::vector<SweepVariant> read_variants(YamlReader& reader, const std::string& source) {
  std::vector<SweepVariant> variants;
  std::set<std::string> variant_names;
  for (YamlReader* item : reader.sequence("variants")) {
    SweepVariant variant;
    item->get("name", variant.name);
    if (variant.name.empty()) item->fail("name", "missing: each variant needs a name");
    item->require("name", variant_names.insert(variant.name).second, "a name no other variant has");
    item->require("name", folder_name(variant.name), kFolderName);
    for (const YamlReader::Item& setting : item->items("settings")) {
      const std::string where = item->key_path("settings") + "." + setting.key;
      require_key_path(setting.key, source, setting.line, where);
      variant.settings.push_back(
          {setting.key, scalar_text(setting.value, source, setting.line, where), setting.line});
    }
    variants.push_back(std::move(variant));
  }
  if (variants.empty()) variants.push_back({"default", {}});
  return variants;
}

/// The grid's parameters: each a settings key with a non-empty list of distinct values.
std::vector<SweepParameter> read_parameters(YamlReader& reader, const std::string& source) {
  std::vector<SweepParameter> parameters;
  for (const YamlReader::Item& item : reader.items("parameters")) {
    SweepParameter parameter{item.key, {}, item.line};
    const std::string path = "parameters." + item.key;
    require_key_path(item.key, source, item.line, path);
    if (!item.value.IsSequence() || item.value.size() == 0)
      throw InputError(source, item.line, path, "expected a non-empty list of values", kKey);
    std::set<std::string> seen;
    for (const YAML::Node& value : item.value) {
      parameter.values.push_back(scalar_text(value, source, item.line, path));
      if (!seen.insert(parameter.values.back()).second)
        throw InputError(source, item.line, path,
                         "value \"" + parameter.values.back() + "\" appears twice", kKey);
    }
    parameters.push_back(std::move(parameter));
  }
  return parameters;
}

}  // namespace

SweepSpec parse_sweep(const std::string& text, const std::filesystem::path& file) {
  const std::string source = file.string();
  YamlReader reader = YamlReader::parse(text, source);
  SweepSpec spec;
  spec.file = file;
  spec.name = file.stem().string();
  reader.get("name", spec.name);
  reader.require("name", folder_name(spec.name), kFolderName);
  std::vector<std::string> experiments, estimators;
  reader.get("experiments", experiments);
  reader.get("estimators", estimators);
  if (experiments.empty()) reader.fail("experiments", "missing: which experiments to run");
  if (estimators.empty()) reader.fail("estimators", "missing: which estimators to run");
  const std::map<std::string, int> experiment_frames = read_experiments(reader, experiments, spec);
  check_estimators(reader, estimators);
  spec.estimators = estimators;
  read_run_size(reader, experiment_frames, spec);
  spec.config = read_config(reader, file);
  spec.variants = read_variants(reader, source);
  spec.parameters = read_parameters(reader, source);
  reader.finish();
  refuse_oversized(spec);
  const std::vector<std::vector<SweepSetting>> points = grid_points(spec);  // within the limit
  refuse_shared_folders(spec, points);

  for (const SweepVariant& variant : spec.variants)
    for (const auto& point : points) {
      std::vector<SweepSetting> settings = variant.settings;
      settings.insert(settings.end(), point.begin(), point.end());
      check_settings(spec, settings);
    }
  return spec;
}

SweepSpec load_sweep(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), 0, "", "cannot read the sweep file");
  std::stringstream text;
  text << in.rdbuf();
  return parse_sweep(text.str(), file);
}

}  // namespace opf::experiments
