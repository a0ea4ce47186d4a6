#pragma once
// A sweep file (`opf sweep SWEEP.yaml`, experiments/sweeps/): which experiments, estimators and
// seeds to run, with which estimator settings. Settings vary two ways, combined: named variants
// (e.g. each OP module off in turn) and a grid of values per option (every combination).
//
//   name: kappa                        # results go to results/sweeps/<name> by default
//   experiments: [general_op]          # bundled names (experiments/<name>.yaml) or paths
//   estimators: [opf]
//   seeds: 5                           # seed indices 0..4: the runs of `opf run --seeds 5`
//   seed: 1                            # base seed (default 1, as `opf run`)
//   particles: 5000                    # per portion; default the settings' (5000)
//   frames: 100                        # track the first frames only (default all)
//   config: my_estimators.yaml         # base estimator settings, relative to this file
//   variants:                          # default: one variant, "default", with no settings
//     - {name: all_on, settings: {}}
//     - {name: no_dynamics, settings: {opf.modules.dynamics: false}}
//   parameters:                        # option key path (or `particles`) -> values
//     opf.uncertainty.kappa: [1.0, 1.01, 1.03, 1.1]
//
// Keys are the paths of experiments/configs/estimators.yaml. Every combination is checked against
// the estimator settings reader when the file is loaded, so a typo fails before any run.

#include "drivers/run_limit.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace opf::experiments {

/// One setting: an option's key path and its value as written (YAML reads it again).
struct SweepSetting {
  std::string key;
  std::string value;
  std::size_t line = 0;  ///< in the sweep file, for errors
};

struct SweepVariant {
  std::string name;
  std::vector<SweepSetting> settings;
};

struct SweepParameter {
  std::string key;
  std::vector<std::string> values;
  std::size_t line = 0;
};

struct SweepSpec {
  std::filesystem::path file;
  std::string name;
  std::vector<std::filesystem::path> experiments;  ///< resolved experiment files
  std::vector<std::string> estimators;
  std::size_t seeds = 5;
  std::uint64_t seed = 1;
  std::optional<std::size_t> particles;
  std::optional<std::size_t> frames;
  std::optional<std::filesystem::path> config;  ///< resolved
  std::vector<SweepVariant> variants;           ///< at least one
  std::vector<SweepParameter> parameters;
};

/// The key that sets `opf run --particles` rather than an estimator option.
inline constexpr const char* kParticlesKey = "particles";

/// The --config contents of a run: the sweep's base config with `settings` set on top (key paths
/// become nested mappings; values are written as they were in the sweep file). `particles` is
/// not an estimator option and is left out.
std::string settings_yaml(const SweepSpec& spec, const std::vector<SweepSetting>& settings);

/// A grid point's folder, under its variant's: `key=value` for each parameter, joined by commas,
/// with '/' and whitespace in a value written as '_' (empty for no parameters).
std::string point_folder(const std::vector<SweepSetting>& point);

/// Every combination of one value per parameter, in file order (the last parameter varies
/// fastest); one empty combination when there are no parameters.
std::vector<std::vector<SweepSetting>> grid_points(const SweepSpec& spec);

/// Reads and checks a sweep file: InputError naming the file, the line and the key for a YAML
/// error, an unknown or mistyped key, an unknown experiment or estimator (each experiment file
/// is read, its own errors naming its lines), two experiments of one name or an estimator twice,
/// `frames` past an experiment's, a sweep or variant name that is not a folder name, a duplicate
/// variant name or value, a setting's key that is not a key path, a value YAML cannot read on its
/// own, two grid points of one folder, more than kMaxRuns runs, and any setting the
/// estimator settings reader rejects.
SweepSpec load_sweep(const std::filesystem::path& file);

/// As load_sweep, from text; `file` names it in errors and anchors relative paths.
SweepSpec parse_sweep(const std::string& text, const std::filesystem::path& file);

}  // namespace opf::experiments
