#include "settings_arguments.h"

#include "opf/core/homogeneous_point.h"
#include "opf/io/estimator_settings_yaml.h"
#include "paper_preset.h"

#include <pybind11/stl.h>

#include <Eigen/Core>

#include <stdexcept>
#include <vector>

namespace py = pybind11;

namespace opf::python {
namespace {

EstimatorSettings preset_settings(const std::string& preset) {
  if (preset == "default") return {};
  if (preset == "paper") return parse_estimator_settings(kPaperPresetYaml, "preset paper");
  throw std::invalid_argument("option 'preset': expected default or paper, got \"" + preset + "\"");
}

// A dict is read as the text of a settings file with the same keys (JSON is YAML), so the same
// checks and messages apply.
EstimatorSettings read_config(const py::object& config, const EstimatorSettings& base) {
  if (py::isinstance<py::dict>(config)) {
    const py::object dumps = py::module_::import("json").attr("dumps");
    return parse_estimator_settings(py::cast<std::string>(dumps(config)), "<config dict>", base);
  }
  const py::object fspath = py::module_::import("os").attr("fspath");
  return load_estimator_settings(py::cast<std::string>(fspath(config)), base);
}

// The particle counts the config itself sets, as opposed to those it inherits.
struct ConfigCounts {
  std::optional<std::size_t> translation;
  std::optional<std::size_t> rotation;
};

// The config over `base`. Read over two bases that differ only in the particle counts, a count
// the config leaves alone comes out different: so the reader itself says which counts it set.
EstimatorSettings with_config(const py::object& config, const EstimatorSettings& base,
                              ConfigCounts& counts) {
  if (config.is_none()) return base;
  EstimatorSettings one = base;
  EstimatorSettings two = base;
  one.pf.translation_particles = one.pf.rotation_particles = 1;
  two.pf.translation_particles = two.pf.rotation_particles = 2;
  EstimatorSettings settings = read_config(config, one);
  const EstimatorSettings other = read_config(config, two);
  const auto settle = [](std::size_t& read, std::size_t again, std::size_t inherited,
                         std::optional<std::size_t>& set) {
    if (read == again)
      set = read;
    else
      read = inherited;
  };
  settle(settings.pf.translation_particles, other.pf.translation_particles,
         base.pf.translation_particles, counts.translation);
  settle(settings.pf.rotation_particles, other.pf.rotation_particles, base.pf.rotation_particles,
         counts.rotation);
  return settings;
}

// [X, Y, Z] or [X, Y, Z, W] (any sequence of numbers), or opf track's --camera text "X,Y,Z[,W]".
std::optional<Eigen::Vector4d> camera_from(const py::object& camera) {
  if (camera.is_none()) return std::nullopt;
  const bool text = py::isinstance<py::str>(camera);
  std::optional<Eigen::Vector4d> point;
  if (text) {
    point = homogeneous_point_from_text(py::cast<std::string>(camera));
  } else {
    try {
      point = homogeneous_point(py::cast<std::vector<double>>(camera));
    } catch (const py::cast_error&) {
    }
  }
  if (!point)
    throw std::invalid_argument("option 'camera': expected " +
                                std::string(kHomogeneousCameraExpectation) + ", got " +
                                (text ? "\"" + py::cast<std::string>(camera) + "\""
                                      : py::cast<std::string>(py::repr(camera))));
  return point;
}

void apply_particles(std::size_t particles, const ConfigCounts& counts,
                     EstimatorSettings& settings) {
  if (particles == 0) throw std::invalid_argument("particles must be at least 1");
  if (particles > kMaxParticlesPerPortion)
    throw std::invalid_argument("particles must be below 2^31");
  const auto refuse_other = [&](const std::string& key, std::optional<std::size_t> set) {
    if (set && *set != particles)
      throw std::invalid_argument("particles=" + std::to_string(particles) +
                                  " and the config's pf." + key + " (" + std::to_string(*set) +
                                  ") contradict each other: give the particle count in one place");
  };
  refuse_other("translation_particles", counts.translation);
  refuse_other("rotation_particles", counts.rotation);
  settings.pf.translation_particles = settings.pf.rotation_particles = particles;
}

}  // namespace

EstimatorSettings settings_from(const SettingsArguments& arguments) {
  ConfigCounts counts;
  EstimatorSettings settings =
      with_config(arguments.config, preset_settings(arguments.preset), counts);
  if (const auto camera = camera_from(arguments.camera))
    settings.opf.occluder.camera_position = *camera;
  if (arguments.particles) apply_particles(*arguments.particles, counts, settings);
  return settings;
}

void require_camera_for_line_of_sight(const EstimatorSettings& settings) {
  if (settings.opf.occluder.plane == OccluderPlane::kLineOfSight &&
      !settings.opf.occluder.camera_position)
    throw std::invalid_argument(
        "opf.occluder.plane is line_of_sight but no camera position is given: pass camera=[X, Y, "
        "Z] (or set opf.occluder.camera_position), or use plane auto (a top-down camera without "
        "one)");
}

}  // namespace opf::python
