#include "drivers/observe_experiment.h"

#include "opf/sim/camera_sensor.h"
#include "opf/sim/noisy_measurement.h"
#include "opf/sim/scripted_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace opf::experiments {

sim::CameraModel camera_of(const sim::ExperimentConfig& config) {
  const auto& c = config.camera;
  return sim::CameraModel::look_at(c.position, c.look_at, c.up,
                                   c.vertical_fov_deg * std::numbers::pi / 180.0, c.width,
                                   c.height);
}

sim::ColourBlobDetectorOptions detection_of(const sim::ExperimentConfig& config) {
  sim::ColourBlobDetectorOptions options;
  // The blob's area is a whole number of pixels: below x exactly when below ceil(x).
  options.min_area_pixels = static_cast<int>(std::ceil(config.measurement.min_area_pixels));
  return options;
}

void refuse_unseen_objects(const sim::ExperimentConfig& config,
                           const std::vector<sim::CameraFrame>& camera) {
  for (const std::string& object : config.objects_of_interest) {
    const bool ever = std::any_of(camera.begin(), camera.end(), [&](const sim::CameraFrame& f) {
      return std::any_of(f.sightings.begin(), f.sightings.end(), [&](const sim::Sighting& s) {
        return s.object == object && sim::measured(s, config.measurement);
      });
    });
    if (!ever) refuse_unseen_object(config, object, camera.size());
  }
}

void refuse_unseen_object(const sim::ExperimentConfig& config, const std::string& object,
                          std::size_t frames) {
  throw std::invalid_argument(
      "experiment '" + config.name + "': the camera measures the object of interest '" + object +
      "' in none of its " + std::to_string(frames) +
      " frames; nothing would be tracked or scored. Check camera (position, look_at, up, "
      "vertical_fov_deg), the body's waypoints and size, and measurement "
      "(min_visible_fraction, min_area_pixels)");
}

Observation observe_experiment(const sim::ExperimentConfig& config, const Progress& progress) {
  if (progress) progress(config.name + ": rendering " + std::to_string(config.frames) + " frames");
  const sim::ScriptedScene scene(config.bodies);
  Observation observation;
  if (config.sensor == sim::SensorKind::kMotionCapture) {
    // Markers on every body: measured directly (noise comes later, per seed), nothing rendered.
    for (int k = 0; k < config.frames; ++k) {
      const double t = k / config.rate;
      const sim::SceneSnapshot snapshot = scene.at(t);
      bool disabled = false;
      for (const sim::Dropout& d : config.dropouts)
        disabled = disabled || (t >= d.from && t < d.to);
      sim::CameraFrame frame{t, {}};
      for (std::size_t i = 0; i < snapshot.bodies.size(); ++i)
        if (snapshot.bodies[i].tracked)
          frame.sightings.push_back({snapshot.bodies[i].name, disabled ? 0.0 : 1.0, !disabled,
                                     snapshot.poses[i].position});
      observation.camera.push_back(frame);
      observation.truth.push_back(snapshot);
    }
    refuse_unseen_objects(config, observation.camera);
    return observation;
  }
  sim::CameraSensor sensor(camera_of(config), {}, detection_of(config));
  for (int k = 0; k < config.frames; ++k) {
    const sim::SceneSnapshot snapshot = scene.at(k / config.rate);
    observation.camera.push_back(sensor.observe(snapshot));
    observation.truth.push_back(snapshot);
  }
  refuse_unseen_objects(config, observation.camera);
  // The longest run of frames without a sighting of the first object of interest.
  int best_start = 0, best_length = 0, start = -1;
  for (int k = 0; k <= config.frames; ++k) {
    bool seen = true;
    if (k < config.frames)
      for (const auto& s : observation.camera[k].sightings)
        if (s.object == config.objects_of_interest.front()) seen = measured(s, config.measurement);
    if (!seen && start < 0) start = k;
    if (seen && start >= 0) {
      if (k - start > best_length) best_start = start, best_length = k - start;
      start = -1;
    }
  }
  observation.snapshot_frame = best_start + best_length / 2;
  sensor.observe(observation.truth[observation.snapshot_frame]);
  observation.snapshot_bgr = sensor.last_image().bgr.clone();
  return observation;
}

}  // namespace opf::experiments
