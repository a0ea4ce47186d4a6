#pragma once
// Reads EstimatorSettings from a YAML file: every key is optional and overrides the default in the
// option structs; unknown keys, wrong types and out-of-range values are errors.
//
// The full format, with the default values:
//
//   pf:
//     translation_particles: 5000        # >= 1
//     rotation_particles: 5000           # >= 1
//     process_noise: {translation: 0.05, rotation: 0.1}        # > 0, m/sqrt(s), rad/sqrt(s)
//     observation_noise: {translation: 0.01, rotation: 0.05}   # > 0, m, rad
//     resampling: {scheme: systematic, every_frame: true, ess_threshold: 0.5}
//   cvkf:
//     acceleration_noise: 0.5                                  # > 0
//     angular_acceleration_noise: 1.0                          # > 0
//     observation_noise: {translation: 0.01, rotation: 0.05}   # > 0
//     initial_velocity_std: 0.5                                # > 0
//     initial_angular_velocity_std: 1.0                        # > 0
//   oapf:
//     particles: {...}                   # the keys of pf:, same defaults
//     occlusion_rate: 0.5                # > 0, 1/s, visible -> occluded
//     reappearance_rate: 1.0             # > 0, 1/s, occluded -> visible
//     miss_probability: 0.1              # in (0, 1]
//     occluded_likelihood_sigmas: 6.0    # > 0
//     spread_growth: 2.0                 # >= 0, 1/s
//
// scheme is one of multinomial, residual, stratified, systematic; ess_threshold is in (0, 1]. An
// empty file gives all defaults.

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
