#pragma once
// A sweep expanded into runs: one per experiment, estimator, variant, grid point and seed, each
// a process of `opf run` with its own directory. A run is done when the runs CSV `opf run` writes
// last is in its directory, so a stopped sweep resumes where it stopped.

#include "drivers/sweep_spec.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace opf::experiments {

struct SweepRun {
  std::filesystem::path experiment_file;
  std::string experiment;  ///< the file's stem, as `opf run` names its outputs
  std::string estimator;
  std::string variant;
  std::vector<SweepSetting> point;  ///< this run's grid values, in the sweep's parameter order
  std::size_t seed_index = 0;
  /// Relative to the sweep's output directory:
  /// <experiment>/<estimator>/<variant>[/<key>=<value>,...]/seed_<k>.
  std::filesystem::path directory;
  std::string settings_yaml;  ///< written to settings.yaml and passed as --config
  std::optional<std::size_t> particles;
  std::optional<std::size_t> frames;
  /// A settings preset under settings.yaml (`opf run --preset`); empty: the defaults.
  std::string preset;

  /// The file whose presence marks the run done: <directory>/<experiment>_runs.csv.
  std::filesystem::path result_file() const;
  /// The arguments after `opf` (run EXPERIMENT --estimators E --seeds 1 --first-seed k ...) for
  /// a run whose directory is `out / directory`.
  std::vector<std::string> arguments(const std::filesystem::path& out) const;
};

/// Every run of the sweep: experiments, then estimators, variants, grid points and seeds (the
/// last varies fastest).
std::vector<SweepRun> expand_sweep(const SweepSpec& spec);

}  // namespace opf::experiments
