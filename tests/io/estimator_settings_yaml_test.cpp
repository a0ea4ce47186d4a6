#include "opf/io/estimator_settings_yaml.h"

#include "opf/io/input_error.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace opf {
namespace {

using PF = mrpt::bayes::CParticleFilter;

/// The InputError parsing `yaml` must raise; fails the test (and returns an empty error) when none.
InputError error_of(const std::string& yaml) {
  try {
    parse_estimator_settings(yaml, "settings.yaml");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << yaml;
  return InputError("", 0, "", "");
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

void expect_defaults(const EstimatorSettings& s) {
  const EstimatorSettings d;
  EXPECT_EQ(s.pf.translation_particles, d.pf.translation_particles);
  EXPECT_EQ(s.pf.rotation_particles, d.pf.rotation_particles);
  EXPECT_EQ(s.pf.process_noise_translation, d.pf.process_noise_translation);
  EXPECT_EQ(s.pf.process_noise_rotation, d.pf.process_noise_rotation);
  EXPECT_EQ(s.pf.observation_noise_translation, d.pf.observation_noise_translation);
  EXPECT_EQ(s.pf.observation_noise_rotation, d.pf.observation_noise_rotation);
  EXPECT_EQ(s.pf.resampling.scheme, d.pf.resampling.scheme);
  EXPECT_EQ(s.pf.resampling.every_frame, d.pf.resampling.every_frame);
  EXPECT_EQ(s.pf.resampling.ess_threshold, d.pf.resampling.ess_threshold);
  EXPECT_EQ(s.pf.reset_gate, d.pf.reset_gate);
  EXPECT_EQ(s.cvkf.acceleration_noise, d.cvkf.acceleration_noise);
  EXPECT_EQ(s.cvkf.angular_acceleration_noise, d.cvkf.angular_acceleration_noise);
  EXPECT_EQ(s.cvkf.observation_noise_translation, d.cvkf.observation_noise_translation);
  EXPECT_EQ(s.cvkf.observation_noise_rotation, d.cvkf.observation_noise_rotation);
  EXPECT_EQ(s.cvkf.initial_velocity_std, d.cvkf.initial_velocity_std);
  EXPECT_EQ(s.cvkf.initial_angular_velocity_std, d.cvkf.initial_angular_velocity_std);
  EXPECT_EQ(s.imm.position_noise, d.imm.position_noise);
  EXPECT_EQ(s.imm.acceleration_noise, d.imm.acceleration_noise);
  EXPECT_EQ(s.imm.jerk_noise, d.imm.jerk_noise);
  EXPECT_EQ(s.imm.mean_sojourn, d.imm.mean_sojourn);
  EXPECT_EQ(s.opf.modules.dynamics, d.opf.modules.dynamics);
  EXPECT_EQ(s.opf.modules.occluder, d.opf.modules.occluder);
  EXPECT_EQ(s.opf.modules.uncertainty, d.opf.modules.uncertainty);
  EXPECT_EQ(s.opf.history_length, d.opf.history_length);
  EXPECT_EQ(s.opf.history_reset_gap, d.opf.history_reset_gap);
  EXPECT_EQ(s.opf.carry_particles, d.opf.carry_particles);
  EXPECT_EQ(s.opf.motion.translation, d.opf.motion.translation);
  EXPECT_EQ(s.opf.motion.rotation, d.opf.motion.rotation);
  EXPECT_EQ(s.opf.motion.test, d.opf.motion.test);
  EXPECT_EQ(s.opf.trajectory.translation_order, d.opf.trajectory.translation_order);
  EXPECT_EQ(s.opf.trajectory.rotation_order, d.opf.trajectory.rotation_order);
  EXPECT_EQ(s.opf.trajectory.loss, d.opf.trajectory.loss);
  EXPECT_EQ(s.opf.trajectory.translation_loss_scale, d.opf.trajectory.translation_loss_scale);
  EXPECT_EQ(s.opf.trajectory.rotation_loss_scale, d.opf.trajectory.rotation_loss_scale);
  EXPECT_EQ(s.opf.trajectory.max_iterations, d.opf.trajectory.max_iterations);
  EXPECT_EQ(s.opf.occluder.epsilon_occ, d.opf.occluder.epsilon_occ);
  EXPECT_EQ(s.opf.occluder.plane, d.opf.occluder.plane);
  EXPECT_EQ(s.opf.occluder.camera_position.has_value(), d.opf.occluder.camera_position.has_value());
  EXPECT_EQ(s.opf.occluder.keep_offset, d.opf.occluder.keep_offset);
  EXPECT_EQ(s.opf.occluder.keep_depth, d.opf.occluder.keep_depth);
  EXPECT_EQ(s.opf.occluder.carry_from_departure, d.opf.occluder.carry_from_departure);
  EXPECT_EQ(s.opf.occluder.departure_margin, d.opf.occluder.departure_margin);
  EXPECT_EQ(s.opf.occluder.orientation_from_estimate, d.opf.occluder.orientation_from_estimate);
  EXPECT_EQ(s.opf.occluder.gate, d.opf.occluder.gate);
  EXPECT_EQ(s.opf.occluder.reach, d.opf.occluder.reach);
  EXPECT_EQ(s.opf.occluder.gate_sigmas, d.opf.occluder.gate_sigmas);
  EXPECT_EQ(s.opf.uncertainty.kappa, d.opf.uncertainty.kappa);
  EXPECT_EQ(s.opf.uncertainty.reference_speed, d.opf.uncertainty.reference_speed);
  EXPECT_EQ(s.opf.uncertainty.reference_period, d.opf.uncertainty.reference_period);
  EXPECT_EQ(s.opf.uncertainty.speed_window, d.opf.uncertainty.speed_window);
  EXPECT_EQ(s.opf.uncertainty.max_scale, d.opf.uncertainty.max_scale);
  EXPECT_EQ(s.opf.feedback.epsilon_safe, d.opf.feedback.epsilon_safe);
  EXPECT_EQ(s.oapf.occlusion_rate, d.oapf.occlusion_rate);
  EXPECT_EQ(s.oapf.reappearance_rate, d.oapf.reappearance_rate);
  EXPECT_EQ(s.oapf.miss_probability, d.oapf.miss_probability);
  EXPECT_EQ(s.oapf.occluded_likelihood_sigmas, d.oapf.occluded_likelihood_sigmas);
  EXPECT_EQ(s.oapf.spread_growth, d.oapf.spread_growth);
}

TEST(EstimatorSettingsYaml, EmptyTextGivesDefaults) {
  expect_defaults(parse_estimator_settings("", "settings.yaml"));
  expect_defaults(parse_estimator_settings("# nothing set\npf: {}\ncvkf:\n", "settings.yaml"));
}

TEST(EstimatorSettingsYaml, EveryKeyOverrides) {
  const EstimatorSettings s = parse_estimator_settings(
      "pf:\n"
      "  translation_particles: 100\n"
      "  rotation_particles: 200\n"
      "  process_noise: {translation: 0.5, rotation: 0.6}\n"
      "  observation_noise: {translation: 0.7, rotation: 0.8}\n"
      "  resampling: {scheme: stratified, every_frame: false, ess_threshold: 1}\n"
      "cvkf:\n"
      "  acceleration_noise: 1.5\n"
      "  angular_acceleration_noise: 2.5\n"
      "  observation_noise:\n"
      "    translation: 0.02\n"
      "    rotation: 0.03\n"
      "  initial_velocity_std: 0.25\n"
      "  initial_angular_velocity_std: 0.75\n",
      "settings.yaml");
  EXPECT_EQ(s.pf.translation_particles, 100u);
  EXPECT_EQ(s.pf.rotation_particles, 200u);
  EXPECT_EQ(s.pf.process_noise_translation, 0.5);
  EXPECT_EQ(s.pf.process_noise_rotation, 0.6);
  EXPECT_EQ(s.pf.observation_noise_translation, 0.7);
  EXPECT_EQ(s.pf.observation_noise_rotation, 0.8);
  EXPECT_EQ(s.pf.resampling.scheme, PF::prStratified);
  EXPECT_FALSE(s.pf.resampling.every_frame);
  EXPECT_EQ(s.pf.resampling.ess_threshold, 1.0);
  EXPECT_EQ(s.cvkf.acceleration_noise, 1.5);
  EXPECT_EQ(s.cvkf.angular_acceleration_noise, 2.5);
  EXPECT_EQ(s.cvkf.observation_noise_translation, 0.02);
  EXPECT_EQ(s.cvkf.observation_noise_rotation, 0.03);
  EXPECT_EQ(s.cvkf.initial_velocity_std, 0.25);
  EXPECT_EQ(s.cvkf.initial_angular_velocity_std, 0.75);
}

TEST(EstimatorSettingsYaml, EveryImmKeyOverrides) {
  const EstimatorSettings s = parse_estimator_settings(
      "imm:\n"
      "  process_noise: {position: 0.1, acceleration: 0.2, jerk: 0.3, angular_acceleration: 0.4}\n"
      "  mean_sojourn: 0.5\n"
      "  observation_noise: {translation: 0.6, rotation: 0.7}\n"
      "  initial_velocity_std: 0.8\n"
      "  initial_acceleration_std: 0.9\n"
      "  initial_angular_velocity_std: 1.1\n",
      "settings.yaml");
  EXPECT_EQ(s.imm.position_noise, 0.1);
  EXPECT_EQ(s.imm.acceleration_noise, 0.2);
  EXPECT_EQ(s.imm.jerk_noise, 0.3);
  EXPECT_EQ(s.imm.angular_acceleration_noise, 0.4);
  EXPECT_EQ(s.imm.mean_sojourn, 0.5);
  EXPECT_EQ(s.imm.observation_noise_translation, 0.6);
  EXPECT_EQ(s.imm.observation_noise_rotation, 0.7);
  EXPECT_EQ(s.imm.initial_velocity_std, 0.8);
  EXPECT_EQ(s.imm.initial_acceleration_std, 0.9);
  EXPECT_EQ(s.imm.initial_angular_velocity_std, 1.1);
}

TEST(EstimatorSettingsYaml, EveryOapfKeyOverrides) {
  const EstimatorSettings s = parse_estimator_settings(
      "oapf:\n"
      "  occlusion_rate: 0.25\n"
      "  reappearance_rate: 3\n"
      "  miss_probability: 1\n"
      "  occluded_likelihood_sigmas: 4.5\n"
      "  spread_growth: 0\n",
      "settings.yaml");
  EXPECT_EQ(s.oapf.occlusion_rate, 0.25);
  EXPECT_EQ(s.oapf.reappearance_rate, 3.0);
  EXPECT_EQ(s.oapf.miss_probability, 1.0);
  EXPECT_EQ(s.oapf.occluded_likelihood_sigmas, 4.5);
  EXPECT_EQ(s.oapf.spread_growth, 0.0);
}

TEST(EstimatorSettingsYaml, EveryOpfKeyOverrides) {
  const EstimatorSettings s = parse_estimator_settings(
      "opf:\n"
      "  modules: {dynamics: false, occluder: false, uncertainty: false}\n"
      "  history_length: 30\n"
      "  carry_particles: false\n"
      "  motion_thresholds: {translation: 0.02, rotation: 0.25}\n"
      "  trajectory: {translation_order: 2, rotation_order: 0}\n"
      "  occluder: {epsilon_occ: 0.5, plane: xy, camera_position: [0.55, 0, 0.8],\n"
      "             keep_depth: false, carry_from_departure: false,\n"
      "             orientation_from_estimate: false, gate: false, reach: 0.3}\n"
      "  uncertainty: {kappa: 1.1, reference_speed: 0.2, max_scale: 100}\n"
      "  feedback: {epsilon_safe: 0.5}\n",
      "settings.yaml");
  const OpfOptions& o = s.opf;
  EXPECT_FALSE(o.modules.dynamics || o.modules.occluder || o.modules.uncertainty);
  EXPECT_EQ(o.history_length, 30u);
  EXPECT_FALSE(o.carry_particles);
  EXPECT_EQ(o.motion.translation, 0.02);
  EXPECT_EQ(o.motion.rotation, 0.25);
  EXPECT_EQ(o.trajectory.translation_order, 2);
  EXPECT_EQ(o.trajectory.rotation_order, 0);
  EXPECT_EQ(o.occluder.epsilon_occ, 0.5);
  EXPECT_EQ(o.occluder.plane, OccluderPlane::kXY);
  ASSERT_TRUE(o.occluder.camera_position.has_value());
  EXPECT_EQ(*o.occluder.camera_position, Eigen::Vector4d(0.55, 0, 0.8, 1));
  EXPECT_FALSE(o.occluder.keep_depth);
  EXPECT_FALSE(o.occluder.carry_from_departure);
  EXPECT_FALSE(o.occluder.orientation_from_estimate);
  EXPECT_FALSE(o.occluder.gate);
  EXPECT_EQ(o.occluder.reach, 0.3);
  EXPECT_EQ(o.uncertainty.kappa, 1.1);
  EXPECT_EQ(o.uncertainty.reference_speed, 0.2);
  EXPECT_EQ(o.uncertainty.max_scale, 100.0);
  EXPECT_EQ(o.feedback.epsilon_safe, 0.5);
}

TEST(EstimatorSettingsYaml, EveryDynamicsKeyOverrides) {
  const EstimatorSettings s = parse_estimator_settings(
      "opf:\n"
      "  velocity_drift: false\n"
      "  detector_noise: false\n"
      "  dynamics:\n"
      "    predictor: paper\n"
      "    models: [velocity, ballistic]\n"
      "    rotation_models: [damped_angular_velocity]\n"
      "    memory: 0.5\n"
      "    up: [0, 1, 0]\n",
      "settings.yaml");
  const OpfOptions& o = s.opf;
  EXPECT_FALSE(o.velocity_drift);
  EXPECT_FALSE(o.detector_noise);
  EXPECT_EQ(o.dynamics.predictor, DynamicsPredictor::kPaper);
  EXPECT_EQ(o.dynamics.models,
            (std::vector<MotionModel>{MotionModel::kConstantVelocity, MotionModel::kBallistic}));
  EXPECT_EQ(o.dynamics.rotation_models,
            std::vector<RotationModel>{RotationModel::kDampedAngularVelocity});
  EXPECT_EQ(o.dynamics.memory, 0.5);
  EXPECT_EQ(o.dynamics.up, Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(error_of("opf:\n  dynamics:\n    memory: -1\n").field(), "opf.dynamics.memory");
  // The message shows the list as written: which name is unknown or repeated.
  const std::string names =
      "expected a list of distinct names, each position, velocity, damped "
      "or ballistic, got ";
  const InputError unknown = error_of("opf:\n  dynamics:\n    models: [velocity, walk]\n");
  EXPECT_EQ(unknown.field(), "opf.dynamics.models");
  EXPECT_EQ(unknown.message(), names + "[velocity, walk]");
  const InputError repeated = error_of("opf:\n  dynamics:\n    models: [velocity, velocity]\n");
  EXPECT_EQ(repeated.field(), "opf.dynamics.models");
  EXPECT_EQ(repeated.message(), names + "[velocity, velocity]");
  const InputError empty = error_of("opf:\n  dynamics:\n    models: []\n");
  EXPECT_EQ(empty.field(), "opf.dynamics.models");
  EXPECT_EQ(empty.message(), "expected a list of names or values, got an empty list");
  EXPECT_EQ(error_of("opf:\n  dynamics:\n    up: [0, 0, 0]\n").message(),
            "expected a non-zero vector, got [0, 0, 0]");
}

TEST(EstimatorSettingsYaml, ParticleOptionsAreSharedNotPerEstimator) {
  // One `pf:` section configures the particle filter of pf, opf and oapf alike; a per-estimator
  // `particles:` key would let paired comparisons drift apart silently, so it is unknown.
  const InputError e = error_of("oapf:\n  particles:\n    translation_particles: 10\n");
  EXPECT_EQ(e.field(), "oapf.particles");
  EXPECT_EQ(e.line(), 2u);
}

TEST(EstimatorSettingsYaml, ShippedConfigDocumentsTheDefaults) {
  expect_defaults(load_estimator_settings(std::filesystem::path(OPF_SOURCE_DIR) / "experiments" /
                                          "configs" / "estimators.yaml"));
}

TEST(EstimatorSettingsYaml, PartialOverrideKeepsOtherDefaults) {
  const EstimatorSettings s =
      parse_estimator_settings("pf:\n  resampling:\n    scheme: residual\n", "settings.yaml");
  EXPECT_EQ(s.pf.resampling.scheme, PF::prResidual);
  const EstimatorSettings d;
  EXPECT_EQ(s.pf.translation_particles, d.pf.translation_particles);
  EXPECT_EQ(s.pf.resampling.every_frame, d.pf.resampling.every_frame);
  EXPECT_EQ(s.cvkf.acceleration_noise, d.cvkf.acceleration_noise);
}

TEST(EstimatorSettingsYaml, UnknownKeyNamesPathLineAndSuggestion) {
  const InputError e = error_of(
      "pf:\n"
      "  translation_particles: 10\n"
      "  resampling:\n"
      "    sheme: residual\n");
  EXPECT_EQ(e.file(), "settings.yaml");
  EXPECT_EQ(e.line(), 4u);
  EXPECT_EQ(e.field(), "pf.resampling.sheme");
  EXPECT_TRUE(contains(e.message(), "did you mean 'scheme'?")) << e.what();

  const InputError particles = error_of("pf:\n  translation_particle: 10\n");
  EXPECT_EQ(particles.line(), 2u);
  EXPECT_TRUE(contains(particles.message(), "did you mean 'translation_particles'?"))
      << particles.what();

  const InputError opf = error_of("opf:\n  uncertainty:\n    kapa: 1.1\n");
  EXPECT_EQ(opf.line(), 3u);
  EXPECT_EQ(opf.field(), "opf.uncertainty.kapa");
  EXPECT_TRUE(contains(opf.message(), "did you mean 'kappa'?")) << opf.what();

  const InputError section = error_of("kf:\n  acceleration_noise: 1\n");
  EXPECT_EQ(section.line(), 1u);
  EXPECT_EQ(section.field(), "kf");
}

TEST(EstimatorSettingsYaml, WrongTypeNamesPathAndLine) {
  const InputError e = error_of("cvkf:\n  acceleration_noise: fast\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "cvkf.acceleration_noise");
  const InputError flag = error_of("pf:\n  resampling: {every_frame: sometimes}\n");
  EXPECT_EQ(flag.line(), 2u);
  EXPECT_EQ(flag.field(), "pf.resampling.every_frame");
  const InputError section = error_of("pf: [1, 2]\n");
  EXPECT_EQ(section.field(), "pf");
}

TEST(EstimatorSettingsYaml, OutOfRangeValuesAreRejected) {
  struct Case {
    const char* yaml;
    const char* field;
    std::size_t line;
  };
  for (const Case& c : {
           Case{"pf:\n  translation_particles: 0\n", "pf.translation_particles", 2},
           Case{"pf:\n  rotation_particles: -5\n", "pf.rotation_particles", 2},
           Case{"pf:\n  rotation_particles: 2.5\n", "pf.rotation_particles", 2},
           // The resampler marks end slots in 32 bits: 2^31 would fail mid-run (or exhaust the
           // memory first), not at the key.
           Case{"pf:\n  translation_particles: 2147483648\n", "pf.translation_particles", 2},
           Case{"pf:\n  process_noise: {translation: 0}\n", "pf.process_noise.translation", 2},
           Case{"pf:\n  observation_noise:\n    rotation: -0.1\n", "pf.observation_noise.rotation",
                3},
           Case{"pf:\n  resampling: {ess_threshold: 0}\n", "pf.resampling.ess_threshold", 2},
           Case{"pf:\n  resampling: {ess_threshold: 1.01}\n", "pf.resampling.ess_threshold", 2},
           Case{"cvkf:\n  initial_velocity_std: 0\n", "cvkf.initial_velocity_std", 2},
           Case{"cvkf:\n  observation_noise: {translation: -1}\n",
                "cvkf.observation_noise.translation", 2},
           Case{"oapf:\n  occlusion_rate: 0\n", "oapf.occlusion_rate", 2},
           Case{"oapf:\n  reappearance_rate: -1\n", "oapf.reappearance_rate", 2},
           Case{"oapf:\n  miss_probability: 0\n", "oapf.miss_probability", 2},
           Case{"oapf:\n  miss_probability: 1.5\n", "oapf.miss_probability", 2},
           Case{"oapf:\n  occluded_likelihood_sigmas: 0\n", "oapf.occluded_likelihood_sigmas", 2},
           Case{"oapf:\n  spread_growth: -0.5\n", "oapf.spread_growth", 2},
           Case{"opf:\n  history_length: 1\n", "opf.history_length", 2},
           Case{"opf:\n  uncertainty: {kappa: 1.0}\n", "opf.uncertainty.kappa", 2},
           Case{"opf:\n  feedback:\n    epsilon_safe: 0\n", "opf.feedback.epsilon_safe", 3},
           Case{"opf:\n  trajectory: {translation_order: 6}\n", "opf.trajectory.translation_order",
                2},
           Case{"opf:\n  occluder: {plane: yz}\n", "opf.occluder.plane", 2},
           Case{"opf:\n  occluder: {camera_position: [1, 2]}\n", "opf.occluder.camera_position", 2},
           Case{"opf:\n  occluder: {epsilon_occ: -0.1}\n", "opf.occluder.epsilon_occ", 2},
           Case{"opf:\n  occluder: {reach: -0.1}\n", "opf.occluder.reach", 2},
           // Past kMaxNoise (1e6) the filters' estimates turn into NaN (some from 1e8 on).
           Case{"pf:\n  observation_noise: {rotation: 1.000001e6}\n",
                "pf.observation_noise.rotation", 2},
           Case{"pf:\n  process_noise: {translation: 1e300}\n", "pf.process_noise.translation", 2},
           Case{"cvkf:\n  acceleration_noise: 1e7\n", "cvkf.acceleration_noise", 2},
           Case{"imm:\n  initial_acceleration_std: 1e20\n", "imm.initial_acceleration_std", 2},
           Case{"imm:\n  process_noise: {jerk: 1e7}\n", "imm.process_noise.jerk", 2},
           Case{"oapf:\n  spread_growth: 1e20\n", "oapf.spread_growth", 2},
       }) {
    const InputError e = error_of(c.yaml);
    EXPECT_EQ(e.field(), c.field) << c.yaml;
    EXPECT_EQ(e.line(), c.line) << c.yaml;
  }
}

TEST(EstimatorSettingsYaml, BadSchemeListsTheFour) {
  const InputError e = error_of("pf:\n  resampling:\n    scheme: bogus\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "pf.resampling.scheme");
  for (const char* name : {"multinomial", "residual", "stratified", "systematic", "bogus"})
    EXPECT_TRUE(contains(e.message(), name)) << e.what();
}

TEST(EstimatorSettingsYaml, LoadsFromFile) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("opf_settings_yaml_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / "settings.yaml";
  std::ofstream(path) << "pf:\n  translation_particles: 42\n";
  const EstimatorSettings s = load_estimator_settings(path);
  EXPECT_EQ(s.pf.translation_particles, 42u);

  std::ofstream(path) << "pf:\n  translation_particles: 0\n";
  try {
    load_estimator_settings(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_EQ(e.line(), 2u);
  }
  EXPECT_THROW(load_estimator_settings(dir / "missing.yaml"), InputError);
  EXPECT_THROW(load_estimator_settings(dir), InputError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace opf
