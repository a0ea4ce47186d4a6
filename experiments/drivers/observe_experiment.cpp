#include "drivers/observe_experiment.h"

#include "sim/camera_sensor.h"
#include "sim/scripted_scene.h"

#include <numbers>

namespace opf::experiments {

sim::CameraModel camera_of(const sim::ExperimentConfig& config) {
  const auto& c = config.camera;
  return sim::CameraModel::look_at(c.position, c.look_at, c.up,
                                   c.vertical_fov_deg * std::numbers::pi / 180.0, c.width,
                                   c.height);
}

Observation observe_experiment(const sim::ExperimentConfig& config, const Progress& progress) {
  if (progress) progress(config.name + ": rendering " + std::to_string(config.frames) + " frames");
  const sim::ScriptedScene scene(config.bodies);
  sim::CameraSensor sensor(camera_of(config));
  Observation observation;
  for (int k = 0; k < config.frames; ++k) {
    const sim::SceneSnapshot snapshot = scene.at(k / config.rate);
    observation.camera.push_back(sensor.observe(snapshot));
    observation.truth.push_back(snapshot);
  }
  return observation;
}

}  // namespace opf::experiments
