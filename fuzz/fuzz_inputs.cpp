#include "fuzz_inputs.h"

#include "drivers/sweep_runs.h"
#include "drivers/sweep_spec.h"

#include "opf/core/option_schema.h"
#include "opf/estimators/estimator_names.h"
#include "opf/io/estimator_settings_yaml.h"
#include "opf/io/input_error.h"
#include "opf/io/log_read_options.h"
#include "opf/io/measurement_log.h"
#include "opf/sim/colour_blob_detector.h"
#include "opf/sim/experiment_config.h"
#include "opf/vision/blob_pose.h"
#include "opf/vision/object_segmenter.h"
#include "opf/vision/segmentation_spec.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace opf::fuzz {
namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::logic_error("fuzz: " + what);
}

// What the reader accepts keeps its promises: frames in increasing time, finite poses, stated
// noises within kMaxNoise.
void check_frame(const Frame& frame, std::optional<double>& last_t) {
  if (last_t && !(*last_t < frame.t)) fail("frames out of order");
  if (!std::isfinite(frame.t)) fail("a non-finite frame time");
  last_t = frame.t;
  for (const Detection& d : frame.detections) {
    for (const double v : d.pose.asVectorVal())
      if (!std::isfinite(v)) fail("a non-finite pose was accepted");
    if (!(d.extra_noise >= 0.0 && d.extra_noise <= kMaxNoise)) fail("an extra noise past 1e6 m");
  }
}

// The bytes as a log in one format, read whole and as a stream (rows must then be in time order).
void read_both_ways(const std::string& text, const LogReadOptions& options) {
  std::istringstream whole(text);
  try {
    const MeasurementLog log = parse_measurement_log(whole, "fuzz.log", options);
    std::optional<double> last_t;
    for (const Frame& frame : log.frames) check_frame(frame, last_t);
  } catch (const InputError&) {
  }
  std::istringstream streamed(text);
  try {
    MeasurementStream stream(streamed, "fuzz.log", options);
    std::optional<double> last_t;
    while (const std::optional<Frame> frame = stream.next()) check_frame(*frame, last_t);
  } catch (const InputError&) {
  }
}

// A name the result files can carry: not empty, within sim::kMaxNameLength, no '/' and not
// "." or "..".
bool file_name_word(const std::string& name) {
  return !name.empty() && name.size() <= sim::kMaxNameLength &&
         name.find('/') == std::string::npos && name != "." && name != "..";
}

// What the experiment reader accepts can be run: frames to step at most 10 s apart, a detector
// noise within kMaxNoise, tracked bodies of a colour the camera can segment and no other body of
// their hue, waypoints within 1e6 m and in time order, and names the result files can carry.
void check_experiment(const sim::ExperimentConfig& config) {
  if (config.frames < 1) fail("an experiment of no frames was accepted");
  if (!(config.rate >= kMinFrameRate)) fail("frames more than 10 s apart");
  if (!(config.measurement.position_noise <= kMaxNoise) ||
      !(config.measurement.orientation_noise <= kMaxNoise))
    fail("a detector noise past 1e6");
  if (config.bodies.empty() || config.objects_of_interest.empty()) fail("nothing to track");
  if (!file_name_word(config.name)) fail("an experiment name that is not a file name");
  for (const sim::ScriptedBody& body : config.bodies) {
    if (!file_name_word(body.body.name)) fail("a body name that is not a file name");
    if (body.waypoints.empty()) fail("a body without waypoints");
    if (body.body.tracked && config.sensor == sim::SensorKind::kCamera &&
        !sim::segmentable(body.body.colour))
      fail("a tracked body the camera cannot segment");
    if (body.body.tracked && config.sensor == sim::SensorKind::kCamera)
      for (const sim::ScriptedBody& other : config.bodies)
        if (&other != &body && sim::confusable(body.body.colour, other.body.colour))
          fail("a body the camera would take for a tracked one");
    for (std::size_t k = 0; k < body.waypoints.size(); ++k) {
      const sim::Waypoint& w = body.waypoints[k];
      if (!std::isfinite(w.t) || !(w.position.lpNorm<Eigen::Infinity>() <= sim::kMaxSceneExtent))
        fail("a waypoint that is not finite or past 1e6 m");
      if (k > 0 && !(body.waypoints[k - 1].t < w.t)) fail("waypoints out of order");
    }
  }
}

// What the spec reader accepts, `opf detect` can run: each object's segmenter takes its options,
// and a sighting becomes a pose under its pose options.
void check_segmentation(const vision::SegmentationSpec& spec) {
  if (spec.objects.empty()) fail("a spec without objects");
  for (const vision::ObjectSpec& object : spec.objects) {
    if (object.name.empty()) fail("an object without a name");
    try {
      const vision::ObjectSegmenter segmenter(object.segmentation);
      const vision::BlobSighting sighting{0, {320.0, 240.0}, 100.0, 0.0};
      vision::blob_poses({&sighting, 1}, object.pose);
    } catch (const std::invalid_argument& e) {
      fail(std::string("accepted options that detection refuses: ") + e.what());
    }
  }
}

// What the sweep reader accepts, `opf sweep` can run: known estimators and experiment files, each
// once, at most kMaxRuns runs, each grid point in a folder of its own, and every run's
// settings file read by the settings reader.
void check_sweep(const experiments::SweepSpec& spec) {
  if (spec.experiments.empty() || spec.estimators.empty()) fail("a sweep of nothing");
  std::set<std::string> names;
  for (const std::filesystem::path& file : spec.experiments)
    if (!std::filesystem::is_regular_file(file) || !names.insert(file.stem().string()).second)
      fail("an experiment missing or twice: " + file.string());
  const std::vector<std::string> known = estimator_names();
  for (std::size_t i = 0; i < spec.estimators.size(); ++i)
    if (std::count(known.begin(), known.end(), spec.estimators[i]) != 1 ||
        std::count(spec.estimators.begin(), spec.estimators.end(), spec.estimators[i]) != 1)
      fail("an estimator unknown or twice: " + spec.estimators[i]);
  if (spec.seeds < 1 || spec.variants.empty()) fail("no seeds or no variants");
  const auto folder_name = [](const std::string& name) {
    return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
  };
  if (!folder_name(spec.name)) fail("a sweep name that is not a folder: " + spec.name);
  for (const experiments::SweepVariant& variant : spec.variants)
    if (!folder_name(variant.name)) fail("a variant name that is not a folder: " + variant.name);
  experiments::SweepSpec one_seed = spec;  // the seeds only add seed_<k> folders
  one_seed.seeds = 1;
  const std::vector<experiments::SweepRun> runs = experiments::expand_sweep(one_seed);
  if (runs.size() * spec.seeds > experiments::kMaxRuns) fail("more runs than the limit");
  std::set<std::filesystem::path> folders;
  for (const experiments::SweepRun& run : runs) {
    if (!folders.insert(run.directory.lexically_normal()).second)
      fail("two runs share the folder " + run.directory.string());
    try {
      parse_estimator_settings(run.settings_yaml, "settings.yaml");
    } catch (const InputError& e) {
      fail(std::string("a run's settings are refused: ") + e.what());
    }
  }
}

}  // namespace

// Every format reads the same bytes: the CSV, a TUM trajectory, MOTChallenge boxes, an ASL CSV,
// KITTI tracking labels.
void measurement_log(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  read_both_ways(text, {});
  for (const LogFormat one_object : {LogFormat::kTum, LogFormat::kEuroc}) {
    LogReadOptions options;
    options.format = one_object;
    options.object = "fuzz";
    read_both_ways(text, options);
  }
  for (const LogFormat framed : {LogFormat::kMot, LogFormat::kKitti}) {
    LogReadOptions boxes;
    boxes.format = framed;
    boxes.rate = 30.0;
    read_both_ways(text, boxes);
  }
}

void estimator_settings(const std::uint8_t* data, std::size_t size) {
  try {
    parse_estimator_settings(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  } catch (const InputError&) {
  }
}

void segmentation_spec(const std::uint8_t* data, std::size_t size) {
  try {
    check_segmentation(vision::parse_segmentation_spec(
        std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml"));
  } catch (const InputError&) {
  }
}

void sweep_file(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const char* special : {"/proc", "/sys", "/dev"})
    if (text.find(special) != std::string::npos) return;
  try {
    check_sweep(experiments::parse_sweep(
        text, std::filesystem::path(OPF_SOURCE_DIR) / "experiments" / "sweeps" / "fuzz.yaml"));
  } catch (const InputError&) {
  }
}

void experiment_file(const std::uint8_t* data, std::size_t size) {
  try {
    check_experiment(
        sim::parse_experiment(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml"));
  } catch (const InputError&) {
  }
}

}  // namespace opf::fuzz
