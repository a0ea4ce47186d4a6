#include "drivers/sweep_runs.h"

namespace opf::experiments {

std::filesystem::path SweepRun::result_file() const {
  return directory / (experiment + "_runs.csv");
}

std::vector<std::string> SweepRun::arguments(const std::filesystem::path& out) const {
  const std::filesystem::path dir = out / directory;
  std::vector<std::string> args = {"run",          experiment_file.string(),
                                   "--estimators", estimator,
                                   "--seeds",      "1",
                                   "--first-seed", std::to_string(seed_index),
                                   "--config",     (dir / "settings.yaml").string(),
                                   "--out",        dir.string(),
                                   "--threads",    "1",
                                   "--no-figures"};
  if (particles) {
    args.push_back("--particles");
    args.push_back(std::to_string(*particles));
  }
  if (frames) {
    args.push_back("--frames");
    args.push_back(std::to_string(*frames));
  }
  if (!preset.empty()) {
    args.push_back("--preset");
    args.push_back(preset);
  }
  return args;
}

std::vector<SweepRun> expand_sweep(const SweepSpec& spec) {
  std::vector<SweepRun> runs;
  const auto points = grid_points(spec);
  for (const std::filesystem::path& experiment_file : spec.experiments)
    for (const std::string& estimator : spec.estimators)
      for (const SweepVariant& variant : spec.variants)
        for (const auto& point : points) {
          std::vector<SweepSetting> settings = variant.settings;
          settings.insert(settings.end(), point.begin(), point.end());
          std::optional<std::size_t> particles = spec.particles;
          for (const SweepSetting& s : settings)
            if (s.key == kParticlesKey) particles = std::stoul(s.value);
          const std::string point_name = point_folder(point);
          const std::string experiment = experiment_file.stem().string();
          std::filesystem::path base = std::filesystem::path(experiment) / estimator / variant.name;
          if (!point_name.empty()) base /= point_name;
          const std::string yaml = settings_yaml(spec, settings);
          for (std::size_t k = 0; k < spec.seeds; ++k)
            runs.push_back({experiment_file, experiment, estimator, variant.name, point, k,
                            base / ("seed_" + std::to_string(k)), yaml, particles, spec.frames,
                            ""});
        }
  return runs;
}

}  // namespace opf::experiments
