#include "estimators/estimator_settings_yaml.h"

#include "io/input_error.h"

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
  EXPECT_EQ(s.cvkf.acceleration_noise, d.cvkf.acceleration_noise);
  EXPECT_EQ(s.cvkf.angular_acceleration_noise, d.cvkf.angular_acceleration_noise);
  EXPECT_EQ(s.cvkf.observation_noise_translation, d.cvkf.observation_noise_translation);
  EXPECT_EQ(s.cvkf.observation_noise_rotation, d.cvkf.observation_noise_rotation);
  EXPECT_EQ(s.cvkf.initial_velocity_std, d.cvkf.initial_velocity_std);
  EXPECT_EQ(s.cvkf.initial_angular_velocity_std, d.cvkf.initial_angular_velocity_std);
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
           Case{"pf:\n  process_noise: {translation: 0}\n", "pf.process_noise.translation", 2},
           Case{"pf:\n  observation_noise:\n    rotation: -0.1\n", "pf.observation_noise.rotation",
                3},
           Case{"pf:\n  resampling: {ess_threshold: 0}\n", "pf.resampling.ess_threshold", 2},
           Case{"pf:\n  resampling: {ess_threshold: 1.01}\n", "pf.resampling.ess_threshold", 2},
           Case{"cvkf:\n  initial_velocity_std: 0\n", "cvkf.initial_velocity_std", 2},
           Case{"cvkf:\n  observation_noise: {translation: -1}\n",
                "cvkf.observation_noise.translation", 2},
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
