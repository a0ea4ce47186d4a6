#include "opf/io/estimator_settings_yaml.h"

#include "opf/io/csv.h"
#include "opf/io/input_error.h"
#include "opf/io/input_file.h"
#include "opf/io/yaml_reader.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace opf {

namespace {

void read_resampling(YamlReader& yaml, ResamplingOptions& options) {
  yaml.get("scheme", kResamplingSchemeNames, options.scheme);
  yaml.get("every_frame", options.every_frame);
  yaml.get("ess_threshold", options.ess_threshold);
  yaml.require("ess_threshold", options.ess_threshold > 0.0 && options.ess_threshold <= 1.0,
               "a number in (0, 1]");
}

void read_pf(YamlReader& yaml, PoseParticleFilterOptions& options) {
  yaml.get_positive("translation_particles", options.translation_particles);
  yaml.get_positive("rotation_particles", options.rotation_particles);
  YamlReader& process = yaml.child("process_noise");
  process.get_positive("translation", options.process_noise_translation);
  process.get_positive("rotation", options.process_noise_rotation);
  YamlReader& observation = yaml.child("observation_noise");
  observation.get_positive("translation", options.observation_noise_translation);
  observation.get_positive("rotation", options.observation_noise_rotation);
  read_resampling(yaml.child("resampling"), options.resampling);
  yaml.get("reset_gate", options.reset_gate);
  yaml.require("reset_gate", options.reset_gate >= 0.0, "a number of sigmas >= 0 (0 disables)");
}

void read_cvkf(YamlReader& yaml, CvKalmanOptions& options) {
  yaml.get_positive("acceleration_noise", options.acceleration_noise);
  yaml.get_positive("angular_acceleration_noise", options.angular_acceleration_noise);
  YamlReader& observation = yaml.child("observation_noise");
  observation.get_positive("translation", options.observation_noise_translation);
  observation.get_positive("rotation", options.observation_noise_rotation);
  yaml.get_positive("initial_velocity_std", options.initial_velocity_std);
  yaml.get_positive("initial_angular_velocity_std", options.initial_angular_velocity_std);
}

void read_oapf(YamlReader& yaml, OcclusionAwarePfOptions& options) {
  yaml.get_positive("occlusion_rate", options.occlusion_rate);
  yaml.get_positive("reappearance_rate", options.reappearance_rate);
  yaml.get("miss_probability", options.miss_probability);
  yaml.require("miss_probability",
               options.miss_probability > 0.0 && options.miss_probability <= 1.0,
               "a number in (0, 1]");
  yaml.get_positive("occluded_likelihood_sigmas", options.occluded_likelihood_sigmas);
  yaml.get("spread_growth", options.spread_growth);
  yaml.require("spread_growth", options.spread_growth >= 0.0, "a number >= 0");
}

void read_order(YamlReader& yaml, std::string_view key, int& order) {
  std::size_t value = static_cast<std::size_t>(order);
  yaml.get(key, value);
  yaml.require(key, value <= 5, "a polynomial order from 0 to 5");
  order = static_cast<int>(value);
}

void read_dynamics(YamlReader& yaml, DynamicsOptions& options) {
  yaml.get("predictor", kDynamicsPredictorNames, options.predictor);
  MotionPredictionOptions& selection = options.selection;
  yaml.get_positive("history_window", selection.history_window);
  std::vector<std::string> windows;
  for (const double w : selection.fit_windows) windows.push_back(csv::format_double(w));
  yaml.get("fit_windows", windows);
  if (!windows.empty()) {
    selection.fit_windows.clear();
    for (const std::string& w : windows) {
      std::size_t used = 0;
      double value = 0.0;
      try {
        value = std::stod(w, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      yaml.require("fit_windows", used == w.size() && value > 0.0 && std::isfinite(value),
                   "a list of positive numbers of seconds");
      selection.fit_windows.push_back(value);
    }
  }
  yaml.get_positive("validation_horizon", selection.validation_horizon);
  yaml.get("validation_memory", selection.validation_memory);
  yaml.require("validation_memory",
               selection.validation_memory >= 0.0 && std::isfinite(selection.validation_memory),
               "seconds >= 0 (0: every validation origin alike)");
  yaml.get("ballistic", selection.ballistic);
  yaml.get("constant_acceleration", selection.constant_acceleration);
  yaml.get("gravity", selection.gravity);
  yaml.require("gravity", selection.gravity >= 0.0, "m/s^2 >= 0");
  std::vector<double> up = {selection.up.x(), selection.up.y(), selection.up.z()};
  yaml.get("up", up, 3);
  if (!up.empty()) {
    selection.up = Eigen::Vector3d(up[0], up[1], up[2]);
    yaml.require("up", selection.up.norm() > 0.0, "a non-zero vector");
  }
  yaml.get_positive("uncertainty_scale", selection.uncertainty_scale);
  yaml.get("settle_time", selection.settle_time);
  yaml.require("settle_time", selection.settle_time >= 0.0, "seconds >= 0");
  yaml.get("onset_guard", selection.onset_guard);
  yaml.require("onset_guard", selection.onset_guard >= 0.0, "seconds >= 0");
  std::size_t iterations = static_cast<std::size_t>(selection.robust_iterations);
  yaml.get("robust_iterations", iterations);
  yaml.require("robust_iterations", iterations <= 20, "an integer from 0 to 20");
  selection.robust_iterations = static_cast<int>(iterations);
}

void read_opf(YamlReader& yaml, OpfOptions& options) {
  YamlReader& modules = yaml.child("modules");
  modules.get("dynamics", options.modules.dynamics);
  modules.get("occluder", options.modules.occluder);
  modules.get("uncertainty", options.modules.uncertainty);

  yaml.get("history_length", options.history_length);
  yaml.require("history_length", options.history_length >= 2, "an integer H >= 2");
  yaml.get("history_reset_gap", options.history_reset_gap);
  yaml.require("history_reset_gap", options.history_reset_gap >= 0.0, "a number of seconds >= 0");
  yaml.get("carry_particles", options.carry_particles);

  yaml.get("velocity_drift", options.velocity_drift);
  yaml.get("adaptive_rotation_noise", options.adaptive_rotation_noise);
  yaml.get_positive("velocity_window", options.velocity_window);
  yaml.get_positive("hold_after", options.hold_after);
  read_dynamics(yaml.child("dynamics"), options.dynamics);

  YamlReader& motion = yaml.child("motion_thresholds");
  motion.get("translation", options.motion.translation);
  motion.require("translation", options.motion.translation >= 0.0, "a distance in m >= 0");
  motion.get("rotation", options.motion.rotation);
  motion.require("rotation", options.motion.rotation >= 0.0, "an angle in rad >= 0");
  motion.get("test", kMotionTestNames, options.motion.test);

  YamlReader& trajectory = yaml.child("trajectory");
  read_order(trajectory, "translation_order", options.trajectory.translation_order);
  read_order(trajectory, "rotation_order", options.trajectory.rotation_order);
  trajectory.get("loss", kRobustLossNames, options.trajectory.loss);
  trajectory.get_positive("translation_loss_scale", options.trajectory.translation_loss_scale);
  trajectory.get_positive("rotation_loss_scale", options.trajectory.rotation_loss_scale);
  std::size_t iterations = static_cast<std::size_t>(options.trajectory.max_iterations);
  trajectory.get_positive("max_iterations", iterations);
  trajectory.require("max_iterations", iterations <= 10000, "an integer from 1 to 10000");
  options.trajectory.max_iterations = static_cast<int>(iterations);

  YamlReader& occluder = yaml.child("occluder");
  occluder.get("epsilon_occ", options.occluder.epsilon_occ);
  occluder.require("epsilon_occ", options.occluder.epsilon_occ >= 0.0, "a number >= 0");
  occluder.get("plane", kOccluderPlaneNames, options.occluder.plane);
  std::vector<double> camera;
  if (const auto& position = options.occluder.camera_position)
    camera = {position->x(), position->y(), position->z()};
  occluder.get("camera_position", camera, 3);
  if (!camera.empty())
    options.occluder.camera_position = Eigen::Vector3d(camera[0], camera[1], camera[2]);
  occluder.get("keep_offset", options.occluder.keep_offset);
  occluder.get("keep_depth", options.occluder.keep_depth);
  occluder.get("carry_from_departure", options.occluder.carry_from_departure);
  occluder.get("orientation_from_estimate", options.occluder.orientation_from_estimate);
  occluder.get("departure_margin", options.occluder.departure_margin);
  occluder.require(
      "departure_margin",
      options.occluder.departure_margin >= 0.0 && std::isfinite(options.occluder.departure_margin),
      "metres >= 0");
  occluder.get("gate", options.occluder.gate);
  occluder.get("reach", options.occluder.reach);
  occluder.require("reach", options.occluder.reach >= 0.0 && std::isfinite(options.occluder.reach),
                   "metres >= 0");
  occluder.get("gate_sigmas", options.occluder.gate_sigmas);
  occluder.require(
      "gate_sigmas",
      options.occluder.gate_sigmas >= 0.0 && std::isfinite(options.occluder.gate_sigmas),
      "a number >= 0");

  YamlReader& uncertainty = yaml.child("uncertainty");
  uncertainty.get("kappa", options.uncertainty.kappa);
  uncertainty.require("kappa", options.uncertainty.kappa > 1.0, "a number kappa > 1");
  uncertainty.get_positive("reference_speed", options.uncertainty.reference_speed);
  uncertainty.get_positive("reference_period", options.uncertainty.reference_period);
  uncertainty.get("speed_window", options.uncertainty.speed_window);
  uncertainty.require("speed_window", options.uncertainty.speed_window >= 0.0, "seconds >= 0");
  uncertainty.get("max_scale", options.uncertainty.max_scale);
  uncertainty.require("max_scale", options.uncertainty.max_scale >= 1.0, "a number >= 1");

  yaml.child("feedback").get_positive("epsilon_safe", options.feedback.epsilon_safe);
}

void read_settings(YamlReader& yaml, EstimatorSettings& settings) {
  read_pf(yaml.child("pf"), settings.pf);
  read_cvkf(yaml.child("cvkf"), settings.cvkf);
  read_opf(yaml.child("opf"), settings.opf);
  read_oapf(yaml.child("oapf"), settings.oapf);
  yaml.finish();
}

}  // namespace

EstimatorSettings parse_estimator_settings(const std::string& yaml_text,
                                           const std::string& source_name,
                                           const EstimatorSettings& base) {
  EstimatorSettings settings = base;
  YamlReader yaml = YamlReader::parse(yaml_text, source_name);
  read_settings(yaml, settings);
  return settings;
}

YAML::Node estimator_settings_node(const EstimatorSettings& settings) {
  // The reader is the schema: reading nothing over `settings` while recording visits every key
  // with its value, so the dump cannot miss an option the reader knows.
  YAML::Node root(YAML::NodeType::Map);
  YamlReader yaml = YamlReader::parse("", "the effective settings");
  yaml.record_into(root);
  EstimatorSettings copy = settings;
  read_settings(yaml, copy);
  return root;
}

std::string dump_estimator_settings(const EstimatorSettings& settings) {
  YAML::Emitter out;
  out << estimator_settings_node(settings);
  return std::string(out.c_str()) + "\n";
}

EstimatorSettings load_estimator_settings(const std::filesystem::path& path,
                                          const EstimatorSettings& base) {
  std::ifstream in = open_input_file(path, "settings file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path.string(), 0, "", "read error");
  return parse_estimator_settings(text.str(), path.string(), base);
}

}  // namespace opf
