#pragma once
// Reads EstimatorSettings from a YAML file: every key is optional and overrides the default in the
// option structs; unknown keys, wrong types and out-of-range values are errors. The keys, their
// ranges and their order are the structs' describe_options() (estimators/estimator_settings.h);
// experiments/configs/estimators.yaml lists every key with its default and meaning (a test keeps
// it equal to the description). An empty file gives all defaults.

#include "opf/estimators/estimator_settings.h"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>

namespace opf {

/// Throws InputError naming the file, the line and the key path of the first problem, also when
/// the file cannot be read.
EstimatorSettings load_estimator_settings(const std::filesystem::path& path,
                                          const EstimatorSettings& base = {});

/// Keys present override `base` (the defaults unless given), so files can be layered.
/// As load_estimator_settings, from text; `source_name` names it in error messages.
EstimatorSettings parse_estimator_settings(const std::string& yaml_text,
                                           const std::string& source_name,
                                           const EstimatorSettings& base = {});

/// Every setting with its value, as YAML in the settings file's shape (so that
/// parse_estimator_settings of it gives `settings` back): `opf config --dump`.
std::string dump_estimator_settings(const EstimatorSettings& settings);
/// The same as a YAML tree (numbers as their shortest exact text): the provenance of result files.
YAML::Node estimator_settings_node(const EstimatorSettings& settings);

}  // namespace opf
