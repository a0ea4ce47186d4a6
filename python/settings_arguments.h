#pragma once
// The estimator settings of the module's `preset`, `config`, `camera` and `particles` arguments,
// applied in the order `opf track` applies its options of those names: the preset, the config on
// top, then the camera and the particle count.

#include "opf/estimators/estimator_settings.h"

#include <pybind11/pybind11.h>

#include <cstddef>
#include <optional>
#include <string>

namespace opf::python {

struct SettingsArguments {
  /// "default" or "paper" (experiments/configs/paper.yaml).
  std::string preset = "default";
  /// None, a settings file's path, or a dict in the file's shape.
  pybind11::object config = pybind11::none();
  /// None, [X, Y, Z] or "X,Y,Z" (m): the occluder module's line of sight starts there; with a
  /// fourth number 0, a camera infinitely far in that direction (core/homogeneous_point.h).
  pybind11::object camera = pybind11::none();
  /// Particles per portion; None: the config's counts, else the defaults (5000).
  std::optional<std::size_t> particles;
};

/// Throws std::invalid_argument (ValueError) naming the argument, also when `particles` and a
/// count the config sets differ; the config's own errors are InputErrors naming file and key.
EstimatorSettings settings_from(const SettingsArguments& arguments);

/// As `opf track`: plane line_of_sight needs a camera position (std::invalid_argument otherwise).
void require_camera_for_line_of_sight(const EstimatorSettings& settings);

}  // namespace opf::python
