#pragma once
// The bundled experiments as the drivers' tests load and run them.

#include "drivers/experiment_run.h"

#include <cstddef>
#include <string>

namespace opf::experiments {

/// experiments/NAME.yaml of this source tree.
inline sim::ExperimentConfig bundled_experiment(const std::string& name) {
  return sim::load_experiment(std::string(OPF_SOURCE_DIR) + "/experiments/" + name + ".yaml");
}

/// The default settings, as `opf run` runs every experiment, with `particles` per portion and the
/// occluder module pointed at the experiment's camera.
inline EstimatorSettings default_settings(const sim::ExperimentConfig& config,
                                          std::size_t particles) {
  EstimatorSettings settings;
  settings.pf.translation_particles = settings.pf.rotation_particles = particles;
  return with_experiment_camera(settings, config);
}

}  // namespace opf::experiments
