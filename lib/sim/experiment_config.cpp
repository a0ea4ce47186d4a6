#include "opf/sim/experiment_config.h"

#include "opf/core/option_schema.h"
#include "opf/io/input_error.h"
#include "opf/io/input_file.h"
#include "opf/io/log_read_options.h"
#include "opf/io/yaml_reader.h"
#include "opf/sim/camera_model.h"
#include "opf/sim/colour_blob_detector.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

namespace opf::sim {
namespace {

Eigen::Vector3d vector3(YamlReader& yaml, std::string_view key, const Eigen::Vector3d& fallback) {
  std::vector<double> v;
  yaml.get(key, v, 3);
  return v.empty() ? fallback : Eigen::Vector3d(v[0], v[1], v[2]);
}

Colour colour(YamlReader& yaml) {
  std::vector<double> v;
  yaml.get("colour", v, 3);
  if (v.empty()) yaml.fail("colour", "expected a colour [r, g, b], each 0-255");
  for (double c : v)
    yaml.require("colour", c >= 0 && c <= 255 && c == std::floor(c), "integers from 0 to 255");
  return {static_cast<std::uint8_t>(v[0]), static_cast<std::uint8_t>(v[1]),
          static_cast<std::uint8_t>(v[2])};
}

// An experiment's and a body's names name the result files (`<experiment>_frames.csv`,
// `<experiment>_<body>_translation_error.png`) and `opf run`'s default folder, so each must be a
// file name on any system, read before a run rather than failing its last write: a word of
// letters, digits, '_', '-' and '.', not starting with '.' or '-', at most kMaxNameLength long.
void require_file_name_word(YamlReader& yaml, std::string_view key, const std::string& name,
                            std::string_view what) {
  const auto allowed = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
  };
  const bool ok = !name.empty() && name.size() <= kMaxNameLength && name.front() != '.' &&
                  name.front() != '-' && std::all_of(name.begin(), name.end(), allowed);
  if (!ok)
    yaml.fail(key, "expected " + std::string(what) + " of 1 to " + std::to_string(kMaxNameLength) +
                       " letters, digits, '_', '-' or '.', not starting with '.' or '-' (it names "
                       "the result files), got \"" +
                       (name.size() <= kMaxNameLength ? name : name.substr(0, 40) + "...") + "\"");
}

Shape shape(YamlReader& yaml) {
  std::string name;
  yaml.get("shape", name);
  if (const auto value = parse_name(kShapeNames, name)) return *value;
  yaml.fail("shape", "expected " + name_list(kShapeNames) + ", got \"" + name + "\"");
}

Eigen::Vector3d size(YamlReader& yaml, Shape s) {
  std::vector<double> v;
  const std::size_t count = s == Shape::kSphere ? 1 : s == Shape::kCylinder ? 2 : 3;
  yaml.get("size", v, count);
  if (v.empty())
    yaml.fail("size", s == Shape::kSphere     ? "expected [radius]"
                      : s == Shape::kCylinder ? "expected [radius, height]"
                                              : "expected [x, y, z] extents");
  for (double x : v) yaml.require("size", x > 0, "positive sizes in metres");
  if (s == Shape::kSphere) return {v[0], v[0], v[0]};
  if (s == Shape::kCylinder) return {v[0], v[0], v[1]};
  return {v[0], v[1], v[2]};
}

ScriptedBody body(YamlReader& yaml) {
  ScriptedBody b;
  yaml.get("name", b.body.name);
  require_file_name_word(yaml, "name", b.body.name, "a body name");
  b.body.shape = shape(yaml);
  b.body.size = size(yaml, b.body.shape);
  b.body.colour = colour(yaml);
  yaml.get("tracked", b.body.tracked);
  yaml.get("rolling", b.rolling);
  for (YamlReader* w : yaml.sequence("waypoints")) {
    Waypoint waypoint;
    w->get("t", waypoint.t);
    waypoint.position = vector3(*w, "position", Eigen::Vector3d::Zero());
    // A rolling body turns by its path over its radius: far-off waypoints overflow the angle.
    w->require("position", waypoint.position.lpNorm<Eigen::Infinity>() <= kMaxSceneExtent,
               "coordinates within 1e6 m of the origin");
    std::vector<double> yaw_pitch_roll;
    w->get("yaw_pitch_roll", yaw_pitch_roll, 3);
    if (!yaw_pitch_roll.empty())
      waypoint.orientation = Eigen::AngleAxisd(yaw_pitch_roll[0], Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(yaw_pitch_roll[1], Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(yaw_pitch_roll[2], Eigen::Vector3d::UnitX());
    if (!b.waypoints.empty() && !(waypoint.t > b.waypoints.back().t))
      w->fail("t", "waypoints must be in increasing time");
    b.waypoints.push_back(waypoint);
  }
  if (b.waypoints.empty()) yaml.fail("waypoints", "expected at least one waypoint");
  if (yaml.has_key("flight")) {
    YamlReader& f = yaml.child("flight");
    ScriptedBody::Flight flight;
    f.get("from", flight.t_start);
    f.get("to", flight.t_end);
    f.require("to", flight.t_end > flight.t_start, "a time after 'from'");
    flight.position = vector3(f, "position", flight.position);
    flight.velocity = vector3(f, "velocity", flight.velocity);
    flight.spin = vector3(f, "spin", flight.spin);
    f.get_positive("gravity", flight.gravity);
    b.flight = flight;
  }
  for (YamlReader* c : yaml.sequence("carried")) {
    CarriedSpan span;
    c->get("from", span.t_start);
    c->get("to", span.t_end);
    c->get("by", span.carrier);
    c->require("to", span.t_end > span.t_start, "a time after 'from'");
    b.carried.push_back(span);
  }
  return b;
}

// The camera finds a tracked body by its hue: a grey or black one it could never find, and
// another body of a hue within its detector's band would be taken for it (two red bodies: the
// ball's estimate follows the mug). Motion capture identifies markers, whatever their colour.
void refuse_colours_the_camera_cannot_tell(const std::vector<ScriptedBody>& bodies,
                                           const std::vector<YamlReader*>& readers) {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].body.tracked && !segmentable(bodies[i].body.colour))
      readers[i]->fail("colour",
                       "expected a saturated colour for a tracked body, which the camera finds "
                       "by its hue (HSV saturation >= 100 and value >= 60 of 255, as [255, 0, "
                       "0]); an untracked body may be grey");
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!bodies[i].body.tracked) continue;
    for (std::size_t j = 0; j < bodies.size(); ++j)
      if (j != i && confusable(bodies[i].body.colour, bodies[j].body.colour))
        readers[j]->fail("colour",
                         "expected a hue more than 20 degrees from that of the tracked "
                         "body '" +
                             bodies[i].body.name +
                             "', which the camera finds by its hue (or an unsaturated "
                             "colour, for a body nobody tracks)");
  }
}

CameraSettings camera_settings(YamlReader& camera) {
  CameraSettings c;
  c.position = vector3(camera, "position", c.position);
  c.look_at = vector3(camera, "look_at", c.look_at);
  c.up = vector3(camera, "up", c.up);
  switch (look_at_fault(c.position, c.look_at, c.up)) {
    case LookAtFault::kTargetAtEye:
      camera.fail("look_at", "expected a point other than the camera's position");
    case LookAtFault::kUpAlongView:
      camera.fail("up", "expected a direction across the line of sight (position to look_at)");
    case LookAtFault::kNone:
      break;
  }
  camera.get_positive("vertical_fov_deg", c.vertical_fov_deg);
  camera.require("vertical_fov_deg", c.vertical_fov_deg < 170, "an angle below 170");
  return c;
}

MeasurementSettings measurement_settings(YamlReader& measurement, const CameraSettings& camera) {
  MeasurementSettings m;
  measurement.get("position_noise", m.position_noise);
  // Up to kMaxNoise, as an estimator's noise settings (core/option_schema.h).
  measurement.require("position_noise", m.position_noise >= 0 && m.position_noise <= kMaxNoise,
                      "a std (m) from 0 to 1e6");
  measurement.get("orientation_noise", m.orientation_noise);
  measurement.require("orientation_noise",
                      m.orientation_noise >= 0 && m.orientation_noise <= kMaxNoise,
                      "a std (rad) from 0 to 1e6");
  measurement.get("min_visible_fraction", m.min_visible_fraction);
  measurement.require("min_visible_fraction",
                      m.min_visible_fraction >= 0 && m.min_visible_fraction <= 1,
                      "a fraction in [0, 1]");
  measurement.get_positive("min_area_pixels", m.min_area_pixels);
  measurement.require("min_area_pixels",
                      m.min_area_pixels <= static_cast<double>(camera.width) * camera.height,
                      "a pixel count up to the image's (640 x 480)");
  measurement.get("state_sizes", m.state_sizes);
  return m;
}

/// The paper preset's settings for this experiment, beside the experiment file; empty: none.
std::filesystem::path paper_preset_config(YamlReader& yaml, const std::string& source) {
  if (yaml.has_key("estimator_config"))
    yaml.fail("estimator_config",
              "an experiment runs the default preset's one set of settings: pass your own to "
              "the command (--config FILE.yaml), or name the paper preset's settings for this "
              "experiment as paper_preset_config");
  std::string name;
  yaml.get("paper_preset_config", name);
  if (name.empty()) return {};
  const std::filesystem::path path = std::filesystem::path(source).parent_path() / name;
  if (!names_regular_file(path)) yaml.fail("paper_preset_config", "no file " + path.string());
  return path;
}

std::vector<Dropout> dropouts(YamlReader& yaml, SensorKind sensor) {
  std::vector<Dropout> result;
  for (YamlReader* d : yaml.sequence("dropouts")) {
    Dropout dropout;
    d->get("from", dropout.from);
    d->get("to", dropout.to);
    d->require("to", dropout.to > dropout.from, "a time after 'from'");
    result.push_back(dropout);
  }
  if (!result.empty() && sensor != SensorKind::kMotionCapture)
    yaml.fail("dropouts", "dropouts are scheduled for the motion-capture sensor only");
  return result;
}

std::vector<std::string> objects_of_interest(YamlReader& yaml,
                                             const std::vector<std::string>& names) {
  std::vector<std::string> result;
  std::string interest;
  yaml.get("objects_of_interest", interest);
  for (std::stringstream list(interest); std::getline(list, interest, ',');) {
    if (std::find(names.begin(), names.end(), interest) == names.end())
      yaml.fail("objects_of_interest", "no body named '" + interest + "'");
    result.push_back(interest);
  }
  if (result.empty())
    yaml.fail("objects_of_interest", "expected the comma-separated names of scored bodies");
  return result;
}

CautiousControllerOptions controller_settings(YamlReader& controller, double rate) {
  CautiousControllerOptions c;
  controller.get_positive("kp_nominal", c.kp_nominal);
  // The hand moves by -k_p e dt a frame: the error shrinks by (1 - k_p dt), which overshoots
  // from k_p dt > 1 and diverges from 2 (a gain of 1e300 sent the hand to infinity).
  controller.require("kp_nominal", c.kp_nominal <= rate,
                     "a gain (1/s) up to the frame rate (k_p dt <= 1: no frame's step "
                     "overshoots the error)");
  controller.get_positive("kd_nominal", c.kd_nominal);
  controller.get_positive("epsilon_safe", c.epsilon_safe);
  controller.get_positive("steepness", c.steepness);
  try {
    validate(c);
  } catch (const std::invalid_argument& e) {
    controller.fail("kd_nominal", e.what());
  }
  return c;
}

ClosedLoopSettings closed_loop(YamlReader& loop, const std::vector<std::string>& names,
                               double rate) {
  ClosedLoopSettings c;
  for (auto [key, out] : {std::pair{"robot", &c.robot}, std::pair{"payload", &c.payload},
                          std::pair{"target", &c.target}}) {
    loop.get(key, *out);
    if (std::find(names.begin(), names.end(), *out) == names.end())
      loop.fail(key, "expected the name of a body, got \"" + *out + "\"");
  }
  loop.get("start_below_y", c.start_below_y);
  loop.get_positive("hover_height", c.hover_height);
  loop.get_positive("release_distance", c.release_distance);
  loop.get_positive("release_trace_ratio", c.release_trace_ratio);
  loop.get_positive("gravity", c.gravity);
  c.controller = controller_settings(loop.child("controller"), rate);
  return c;
}

}  // namespace

ExperimentConfig parse_experiment(const std::string& yaml_text, const std::string& source) {
  YamlReader yaml = YamlReader::parse(yaml_text, source);
  ExperimentConfig config;
  yaml.get("name", config.name);
  require_file_name_word(yaml, "name", config.name, "the experiment's name");
  yaml.get_positive("rate", config.rate);
  // As a log's (io/log_read_options.h): frames further apart are not a tracking run, and a rate
  // near zero makes the frame interval overflow.
  yaml.require("rate", is_frame_rate(config.rate), std::string(kFrameRateExpectation));
  std::size_t frames = 0;
  yaml.get_positive("frames", frames);
  // The frame counter is an int: a larger count would wrap around to a few frames or none.
  yaml.require("frames", frames <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
               "a frame count below 2^31");
  config.frames = static_cast<int>(frames);
  config.camera = camera_settings(yaml.child("camera"));
  config.measurement = measurement_settings(yaml.child("measurement"), config.camera);
  config.paper_preset_config = paper_preset_config(yaml, source);

  const std::vector<YamlReader*> body_readers = yaml.sequence("bodies");
  for (YamlReader* b : body_readers) config.bodies.push_back(body(*b));
  if (config.bodies.empty()) yaml.fail("bodies", "expected at least one body");
  std::vector<std::string> names;
  for (const auto& b : config.bodies) names.push_back(b.body.name);
  yaml.get("sensor", kSensorKindNames, config.sensor);
  if (config.sensor == SensorKind::kCamera)
    refuse_colours_the_camera_cannot_tell(config.bodies, body_readers);
  config.dropouts = dropouts(yaml, config.sensor);
  config.objects_of_interest = objects_of_interest(yaml, names);
  if (yaml.has_key("closed_loop"))
    config.closed_loop = closed_loop(yaml.child("closed_loop"), names, config.rate);
  yaml.finish();
  if (config.frames == 0) throw InputError(source, 0, "frames", "expected a frame count >= 1");
  try {
    const ScriptedScene check(config.bodies);  // unknown carriers, carry cycles
  } catch (const std::invalid_argument& e) {
    throw InputError(source, 0, "bodies", e.what());
  }
  return config;
}

ExperimentConfig load_experiment(const std::filesystem::path& path) {
  std::ifstream in = open_input_file(path, "experiment file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_experiment(text.str(), path.string());
}

}  // namespace opf::sim
