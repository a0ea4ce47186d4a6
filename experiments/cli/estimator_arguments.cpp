#include "estimator_arguments.h"

#include "estimators/estimator_settings_yaml.h"

#include <algorithm>
#include <thread>

namespace opf::cli {

std::vector<OptionSpec> estimator_option_specs() {
  return {
      {"config", "FILE.yaml", "estimator options (see experiments/configs/estimators.yaml)"},
      {"particles", "N", "particles per portion (translation and rotation); default 5000"},
      {"seed", "S", "seed of every random draw; the same seed gives identical output (default 1)"},
      {"threads", "N",
       "threads that step the objects of a frame (default: the machine's cores); the output is "
       "the same for any N"},
  };
}

EstimatorSettings settings_from(const Arguments& args, const EstimatorSettings& base) {
  EstimatorSettings settings = base;
  if (const auto path = args.get("config")) settings = load_estimator_settings(*path, settings);
  if (const auto particles = args.get_count("particles")) {
    if (*particles == 0) throw UsageError{"option '--particles' must be at least 1"};
    settings.pf.translation_particles = settings.pf.rotation_particles = *particles;
  }
  return settings;
}

std::size_t threads_from(const Arguments& args) {
  if (const auto threads = args.get_count("threads")) {
    if (*threads == 0) throw UsageError{"option '--threads' must be at least 1"};
    return *threads;
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

std::uint64_t seed_from(const Arguments& args) {
  return args.get_count("seed").value_or(kDefaultSeed);
}

}  // namespace opf::cli
