#include "estimator_arguments.h"

#include "cli/presets.h"
#include "drivers/run_limit.h"
#include "opf/core/homogeneous_point.h"
#include "opf/estimators/registry.h"
#include "opf/io/estimator_settings_yaml.h"

#include <algorithm>
#include <limits>
#include <string>
#include <thread>
#include <vector>

namespace opf::cli {

std::vector<OptionSpec> estimator_option_specs() {
  return {
      {"preset", "NAME",
       "default (the toolkit's one set of settings for every run) or paper (the paper's literal "
       "rules, experiments/configs/paper.yaml, then an experiment's paper_preset_config); "
       "--config is applied on top"},
      {"config", "FILE.yaml", "estimator options (see experiments/configs/estimators.yaml)"},
      {"camera", "X,Y,Z",
       "the camera's position in the world frame (m): the occluder module's line of sight runs "
       "from it; X,Y,Z,0: a camera infinitely far in that direction, every line of sight "
       "parallel (a log of opf detect: 0,0,-1,0) (default: straight down; experiments pass "
       "their own)"},
      {"particles", "N", "particles per portion (translation and rotation); default 5000"},
      {"seed", "S", "seed of every random draw; the same seed gives identical output (default 1)"},
      {"threads", "N",
       "threads that step the objects of a frame, at most 256 (default: the machine's cores); "
       "the output is the same for any N"},
  };
}

EstimatorSettings preset_settings(const std::string& preset,
                                  const std::filesystem::path& paper_preset_config) {
  if (preset == "default") return {};
  if (preset != "paper")
    throw UsageError{"option '--preset': expected default or paper, got \"" + preset + "\""};
  EstimatorSettings settings = parse_estimator_settings(kPaperPresetYaml, "preset paper");
  if (!paper_preset_config.empty())
    settings = load_estimator_settings(paper_preset_config, settings);
  return settings;
}

EstimatorSettings settings_from(const Arguments& args,
                                const std::filesystem::path& paper_preset_config) {
  EstimatorSettings settings =
      preset_settings(args.get("preset").value_or("default"), paper_preset_config);
  if (const auto path = args.get("config")) settings = load_estimator_settings(*path, settings);
  if (const auto camera = args.get("camera")) {
    const std::optional<Eigen::Vector4d> point = homogeneous_point_from_text(*camera);
    if (!point)
      throw UsageError{"option '--camera': expected " + std::string(kHomogeneousCameraExpectation) +
                       ", got \"" + *camera + "\""};
    settings.opf.occluder.camera_position = point;
  }
  if (const auto particles = args.get_count("particles")) {
    if (*particles == 0 || *particles > kMaxParticlesPerPortion)
      throw UsageError{"option '--particles' must be a positive integer below 2^31"};
    settings.pf.translation_particles = settings.pf.rotation_particles = *particles;
  }
  return settings;
}

void require_camera_for_line_of_sight(const EstimatorSettings& settings) {
  if (settings.opf.occluder.plane == OccluderPlane::kLineOfSight &&
      !settings.opf.occluder.camera_position)
    throw UsageError{
        "opf.occluder.plane is line_of_sight but no camera position is given: pass --camera "
        "X,Y,Z (or set opf.occluder.camera_position), or use plane auto (a top-down camera "
        "without one)"};
}

bool assumes_top_down_camera(const EstimatorSettings& settings) {
  const OccluderOptions& occluder = settings.opf.occluder;
  return settings.opf.modules.occluder && occluder.plane == OccluderPlane::kAuto &&
         !occluder.camera_position;
}

std::string missing_camera_warning(const std::string& command) {
  return "opf " + command +
         ": warning: no camera position (--camera X,Y,Z, or X,Y,Z,0 for a camera infinitely far "
         "in that direction, or opf.occluder.camera_position): the occluder module takes the "
         "line of sight as straight down (-z); a log of `opf detect`, whose z is the depth, "
         "wants --camera 0,0,-1,0\n";
}

std::size_t threads_from(const Arguments& args) {
  if (const auto threads = args.get_count("threads")) {
    if (*threads == 0) throw UsageError{"option '--threads' must be at least 1"};
    // The pool starts every thread up front, each with its stack: beyond a few per core they
    // only cost memory.
    if (*threads > kMaxThreads)
      throw UsageError{"option '--threads' must be at most " + std::to_string(kMaxThreads) +
                       ", got " + std::to_string(*threads)};
    return *threads;
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

void require_known_estimators(const std::string& option, const std::vector<std::string>& names) {
  const std::vector<std::string> known = estimator_names();
  for (const std::string& name : names)
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw UsageError{"option '--" + option + "': " + unknown_estimator_message(name)};
}

std::uint64_t seed_from(const Arguments& args) {
  return args.get_count("seed").value_or(kDefaultSeed);
}

std::size_t seeds_from(const Arguments& args, std::size_t runs_per_seed) {
  const unsigned long long seeds = args.get_count("seeds").value_or(5);
  if (seeds == 0) throw UsageError{"option '--seeds' must be at least 1"};
  const std::size_t per_seed = std::max<std::size_t>(runs_per_seed, 1);
  if (seeds > experiments::kMaxRuns / per_seed)
    throw UsageError{"option '--seeds' must be at most " +
                     std::to_string(experiments::kMaxRuns / per_seed) + " here (" +
                     std::to_string(per_seed) + (per_seed == 1 ? " run" : " runs") +
                     " a seed, at most " + std::to_string(experiments::kMaxRuns) +
                     " runs a command), got " + std::to_string(seeds)};
  const unsigned long long first = args.get_count("first-seed").value_or(0);
  if (first > std::numeric_limits<std::uint64_t>::max() - seeds)
    throw UsageError{"option '--first-seed' must leave room for " + std::to_string(seeds) +
                     " seeds below 2^64, got " + std::to_string(first)};
  return static_cast<std::size_t>(seeds);
}

}  // namespace opf::cli
