#pragma once
// An experiment as a user writes it (experiments/*.yaml): the scripted scene, the camera, the
// measurement model and which objects the results table scores.

#include "opf/control/cautious_tracking_controller.h"
#include "opf/sim/scripted_scene.h"

#include <Eigen/Core>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace opf::sim {

struct CameraSettings {
  Eigen::Vector3d position = Eigen::Vector3d(0.55, 0.0, 0.49);  ///< paper experiment 1
  Eigen::Vector3d look_at = Eigen::Vector3d(0.55, 0.0, 0.0);
  /// World direction that points up in the image; world x for the paper's top-down cameras.
  Eigen::Vector3d up = Eigen::Vector3d::UnitX();
  double vertical_fov_deg = 75.0;
  int width = 640;
  int height = 480;
};

/// How the rendered image becomes a measurement (paper Sec. IV-B): colour blobs give the
/// position; a marker-style sensor gives the orientation.
/// m: the farthest a waypoint may lie from the origin, on any axis.
inline constexpr double kMaxSceneExtent = 1e6;

struct MeasurementSettings {
  /// Extra noise on the detected position, m per axis: the renderer is exact, a real camera and
  /// detector are not.
  double position_noise = 0.002;
  /// Noise of the marker-style orientation sensor, rad per tangent axis.
  double orientation_noise = 0.01;
  /// An object is measured only when at least this fraction of its silhouette is visible (the
  /// marker must be seen); the position is then the visible blob's centroid, biased when partly
  /// covered, as in reality.
  double min_visible_fraction = 0.3;
  /// A largest blob smaller than this many pixels counts as no detection (the colour detector's
  /// ColourBlobDetectorOptions::min_area_pixels).
  double min_area_pixels = 30.0;
  /// Whether each detection states the body's silhouette radius and bounding box
  /// (Detection::radius, Detection::box), as a detector that knows the objects' models does;
  /// false: the pose alone, as from most pose detectors, and the occluder module measures how far
  /// a cover reaches (docs/occluder.md).
  bool state_sizes = true;
};

/// A robot end-effector driven in closed loop by the cautious tracking controller (paper Eq. 16)
/// towards an estimator's estimate of a target, releasing a payload over it (paper experiment 2).
struct ClosedLoopSettings {
  std::string robot;    ///< the driven body (the end-effector)
  std::string payload;  ///< the body held under the robot until released (the sugar cube)
  std::string target;   ///< the tracked body the robot follows (the mug)
  /// Tracking starts once the target's estimate passes below this y (paper: "once it passes
  /// [0.55, 0.25, 0]").
  double start_below_y = 0.25;
  double hover_height = 0.2;  ///< m above the target's estimated centre
  CautiousControllerOptions controller;
  /// Release when the robot is over the target's estimate within this distance (m) and the
  /// uncertainty U = trace(Q~) is at most release_trace_ratio times its nominal value.
  double release_distance = 0.015;
  double release_trace_ratio = 1.5;
  double gravity = 9.81;
};

/// The paper's other sensor (baseball experiment): motion capture measures every body directly
/// (measurement.position_noise and orientation_noise apply), at the experiment's rate, except
/// during scheduled dropouts when the capture is disabled.
struct Dropout {
  double from = 0.0;  ///< s, inclusive
  double to = 0.0;    ///< s, exclusive
};

enum class SensorKind { kCamera, kMotionCapture };
inline constexpr EnumNames<SensorKind, 2> kSensorKindNames = {
    {{SensorKind::kCamera, "camera"}, {SensorKind::kMotionCapture, "motion_capture"}}};

/// The longest experiment or body name (characters): two of them and the longest suffix a
/// result file adds stay far within a file name's 255 bytes.
inline constexpr std::size_t kMaxNameLength = 64;

struct ExperimentConfig {
  /// Names the result files and `opf run`'s default folder: 1 to kMaxNameLength letters, digits,
  /// '_', '-' and '.', not starting with '.' or '-' (as every body's name).
  std::string name;
  SensorKind sensor = SensorKind::kCamera;
  std::vector<Dropout> dropouts;  ///< motion capture only
  double rate = 30.0;             ///< frames per second (paper: camera rate)
  int frames = 0;
  CameraSettings camera;
  MeasurementSettings measurement;
  std::vector<ScriptedBody> bodies;
  /// The objects whose errors the results table reports (the paper scores the occluded object).
  std::vector<std::string> objects_of_interest;
  /// Estimator settings this experiment runs with under the `paper` preset only (a file in
  /// estimators.yaml's format, resolved against the experiment file's folder), applied on the
  /// preset and under the user's --config: the paper sets its thresholds "for the current
  /// experiment setup" (footnote to Eq. 10). The default preset is one set of settings for every
  /// experiment: an experiment file cannot change it. Empty: the preset alone.
  std::filesystem::path paper_preset_config;
  /// Set for closed-loop experiments (sugar dropping); open loop otherwise.
  std::optional<ClosedLoopSettings> closed_loop;

  bool is_of_interest(const std::string& object) const {
    return std::find(objects_of_interest.begin(), objects_of_interest.end(), object) !=
           objects_of_interest.end();
  }
};

/// Throws InputError naming the file, line and key for anything malformed: unknown keys, wrong
/// types, unknown shapes, carriers or objects of interest, waypoints out of time order.
ExperimentConfig load_experiment(const std::filesystem::path& path);
ExperimentConfig parse_experiment(const std::string& yaml_text, const std::string& source);

}  // namespace opf::sim
