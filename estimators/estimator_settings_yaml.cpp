#include "estimators/estimator_settings_yaml.h"

#include "io/input_error.h"
#include "io/yaml_reader.h"
#include "particles/resampling_scheme_names.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace opf {

namespace {

void read_resampling(YamlReader& yaml, ResamplingOptions& options) {
  std::string scheme(to_string(options.scheme));
  yaml.get("scheme", scheme);
  try {
    options.scheme = parse_resampling_scheme(scheme);
  } catch (const std::invalid_argument&) {
    yaml.fail("scheme",
              "expected multinomial, residual, stratified or systematic, got \"" + scheme + "\"");
  }
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

}  // namespace

EstimatorSettings parse_estimator_settings(const std::string& yaml_text,
                                           const std::string& source_name) {
  EstimatorSettings settings;
  YamlReader yaml = YamlReader::parse(yaml_text, source_name);
  read_pf(yaml.child("pf"), settings.pf);
  read_cvkf(yaml.child("cvkf"), settings.cvkf);
  yaml.finish();
  return settings;
}

EstimatorSettings load_estimator_settings(const std::filesystem::path& path) {
  // Reading a directory "succeeds" with no content, which would silently mean all defaults.
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored))
    throw InputError(path.string(), 0, "", "expected a settings file, got a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path.string(), 0, "",
                     std::string("cannot open the settings file: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path.string(), 0, "", "read error");
  return parse_estimator_settings(text.str(), path.string());
}

}  // namespace opf
