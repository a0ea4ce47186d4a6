#pragma once
// The options every estimator-running subcommand shares: --config, --particles, --seed,
// --threads.

#include "arguments.h"
#include "opf/estimators/estimator_settings.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace opf::cli {

std::vector<OptionSpec> estimator_option_specs();

/// For a log (track, evaluate), where no experiment supplies its camera: `line_of_sight` without
/// a camera position is a usage error, not a silent top-down camera.
void require_camera_for_line_of_sight(const EstimatorSettings& settings);

/// Whether the OPF's occluder module would take the line of sight as straight down for want of a
/// camera (plane auto): a log of several objects gets missing_camera_warning() then.
bool assumes_top_down_camera(const EstimatorSettings& settings);
/// What is assumed, and the camera a log of `opf detect` wants; `command` names the sender.
std::string missing_camera_warning(const std::string& command);

/// The settings a preset starts from: `default`, the defaults; `paper`, its settings, then
/// `paper_preset_config` when given (an experiment's own under that preset). UsageError for any
/// other name.
EstimatorSettings preset_settings(const std::string& preset,
                                  const std::filesystem::path& paper_preset_config = {});

/// preset_settings(--preset, paper_preset_config), then the YAML file of --config, then --camera
/// and --particles (both portions).
EstimatorSettings settings_from(const Arguments& args,
                                const std::filesystem::path& paper_preset_config = {});

/// The most threads --threads takes.
constexpr std::size_t kMaxThreads = 256;

/// --threads (1 to kMaxThreads; UsageError otherwise), or the machine's hardware threads.
std::size_t threads_from(const Arguments& args);

/// Every name of `names` is a registered estimator; else a UsageError naming `option`.
void require_known_estimators(const std::string& option, const std::vector<std::string>& names);

/// --seed, or the toolkit's default seed.
std::uint64_t seed_from(const Arguments& args);

/// --seeds (default 5): at least 1, and at most experiments::kMaxRuns runs at `runs_per_seed` (the
/// estimators, times the experiments); with --first-seed, the last seed's index must fit in 64
/// bits. UsageError otherwise, with the figures.
std::size_t seeds_from(const Arguments& args, std::size_t runs_per_seed);

constexpr std::uint64_t kDefaultSeed = 1;

}  // namespace opf::cli
