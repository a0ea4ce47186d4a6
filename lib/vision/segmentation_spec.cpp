#include "opf/vision/segmentation_spec.h"

#include "opf/io/csv.h"
#include "opf/io/input_error.h"
#include "opf/io/input_file.h"
#include "opf/io/yaml_reader.h"

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

namespace opf::vision {

namespace {

constexpr auto kKey = InputError::FieldKind::kKey;

std::string list(const std::vector<double>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += ", ";
    text += csv::format_double(values[i]);
  }
  text += ']';
  return text;
}

bool whole_in(double value, double low, double high) {
  return value == std::floor(value) && value >= low && value <= high;
}

/// A required [h, s, v] triple of whole numbers in OpenCV's 8-bit HSV ranges.
std::array<int, 3> read_hsv(YamlReader& yaml, std::string_view key) {
  if (!yaml.has_key(key)) yaml.fail(key, "missing; expected " + std::string(key) + ": [h, s, v]");
  std::vector<double> hsv;
  yaml.get(key, hsv, 3);
  if (!whole_in(hsv[0], 0, 179) || !whole_in(hsv[1], 0, 255) || !whole_in(hsv[2], 0, 255))
    yaml.fail(key,
              "expected [h, s, v] of whole numbers with h in 0..179 (OpenCV's hue, degrees / 2) "
              "and s, v in 0..255, got " +
                  list(hsv));
  return {static_cast<int>(hsv[0]), static_cast<int>(hsv[1]), static_cast<int>(hsv[2])};
}

void read_hsv_range(YamlReader& yaml, HsvRange& range) {
  range.low = read_hsv(yaml, "low");
  range.high = read_hsv(yaml, "high");
  if (range.low[1] > range.high[1] || range.low[2] > range.high[2]) {
    const auto text = [](const std::array<int, 3>& v) {
      return list(
          {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])});
    };
    yaml.fail("high", "expected saturation and value at least those of low " + text(range.low) +
                          " (only the hue may wrap around), got " + text(range.high));
  }
}

int read_grey_level(YamlReader& yaml, std::string_view key) {
  std::size_t level = 0;
  yaml.get(key, level);
  yaml.require(key, level <= 255, "a grey level from 0 to 255");
  return static_cast<int>(level);
}

void read_background(YamlReader& yaml, BackgroundOptions& options) {
  if (!yaml.has_key("start"))
    yaml.fail("start", "missing; expected the object's pixel position [u, v] at start_frame");
  std::vector<double> start;
  yaml.get("start", start, 2);
  options.start = cv::Point2d(start[0], start[1]);
  yaml.get("start_frame", options.start_frame);
  yaml.get_positive("gate", options.gate_px);
  std::size_t history = static_cast<std::size_t>(options.history);
  yaml.get_positive("history", history);
  yaml.require("history", history <= 100000, "a number of frames from 1 to 100000");
  options.history = static_cast<int>(history);
  yaml.get_positive("var_threshold", options.var_threshold);
  yaml.get("shadows", options.shadows);
  yaml.get("learning_rate", options.learning_rate);
  yaml.require("learning_rate",
               options.learning_rate == -1.0 ||
                   (options.learning_rate >= 0.0 && options.learning_rate <= 1.0),
               "a rate in [0, 1], or -1 for automatic");
}

void read_morphology(YamlReader& yaml, SegmenterOptions& options) {
  for (const auto& [key, size] :
       {std::pair{"open", &options.open_px}, {"close", &options.close_px}}) {
    std::size_t value = static_cast<std::size_t>(*size);
    yaml.get(key, value);
    yaml.require(key, value <= 255, "a kernel size in px from 0 to 255 (0 or 1: none)");
    *size = static_cast<int>(value);
  }
}

void read_roi(YamlReader& yaml, cv::Rect& roi) {
  std::vector<double> values;
  yaml.get("roi", values, 4);
  if (values.empty()) return;
  const bool ok = whole_in(values[0], 0, 1e6) && whole_in(values[1], 0, 1e6) &&
                  whole_in(values[2], 1, 1e6) && whole_in(values[3], 1, 1e6);
  if (!ok)
    yaml.fail("roi",
              "expected [x, y, width, height] in whole pixels, x, y >= 0 and width, height >= 1, "
              "got " +
                  list(values));
  roi = cv::Rect(static_cast<int>(values[0]), static_cast<int>(values[1]),
                 static_cast<int>(values[2]), static_cast<int>(values[3]));
}

void read_pose(YamlReader& yaml, BlobPoseOptions& options) {
  yaml.get_positive("metres_per_pixel", options.metres_per_pixel);
  yaml.get_positive("reference_depth", options.reference_depth);
  if (yaml.has_key("reference_area")) {
    double area = 0.0;
    yaml.get_positive("reference_area", area);
    options.reference_area = area;
  }
  yaml.get_positive("reference_frames", options.reference_frames);
}

ObjectSpec read_object(YamlReader& yaml, const std::string& name, const std::string& path,
                       std::size_t line) {
  ObjectSpec object;
  object.name = name;
  SegmenterOptions& s = object.segmentation;

  std::string method;
  for (const auto& [value, key] : kSegmentationMethodNames) {
    if (!yaml.has_key(key)) continue;
    if (!method.empty())
      yaml.fail(key, "give one segmentation per object, not both '" + method + "' and '" +
                         std::string(key) + "'");
    method = key;
    s.method = value;
  }
  if (method.empty())
    throw InputError(yaml.source(), line, path,
                     "object '" + name + "' has no segmentation; expected one of the keys " +
                         name_list(kSegmentationMethodNames),
                     kKey);
  if (s.method == SegmentationMethod::kHsv)
    read_hsv_range(yaml.child("hsv"), s.hsv);
  else if (s.method == SegmentationMethod::kBackground)
    read_background(yaml.child("background"), s.background);
  else
    s.grey_threshold = read_grey_level(yaml, method);

  read_morphology(yaml.child("morphology"), s);
  YamlReader& fragments = yaml.child("fragments");
  fragments.get("fraction", s.fragment_fraction);
  fragments.require("fraction", s.fragment_fraction >= 0.0 && s.fragment_fraction <= 1.0,
                    "a fraction of the chosen component's area in [0, 1]");
  fragments.get("distance", s.fragment_distance_px);
  fragments.require("distance", s.fragment_distance_px >= 0.0, "a distance in px >= 0");
  read_roi(yaml, s.roi);
  yaml.get("min_area", s.min_area_px);
  yaml.require("min_area", s.min_area_px >= 0.0, "an area in px >= 0");
  read_pose(yaml.child("pose"), object.pose);
  return object;
}

}  // namespace

SegmentationSpec parse_segmentation_spec(const std::string& text, const std::string& source_name) {
  YamlReader yaml = YamlReader::parse(text, source_name);
  if (!yaml.has_key("objects"))
    yaml.fail("objects", "missing; expected a mapping from object names to their segmentation");
  SegmentationSpec spec;
  // Each object's reader is checked (unknown keys) right after it is read.
  for (const YamlReader::Item& item : yaml.items("objects")) {
    const std::string path = "objects." + item.key;
    if (item.key.empty())
      throw InputError(source_name, item.line, "objects", "expected an object name, got \"\"",
                       kKey);
    for (const ObjectSpec& earlier : spec.objects)
      if (earlier.name == item.key)
        throw InputError(source_name, item.line, path, "object named twice", kKey);
    YamlReader object(item.value, path, source_name);
    spec.objects.push_back(read_object(object, item.key, path, item.line));
    object.finish();
  }
  if (spec.objects.empty())
    yaml.fail("objects", "expected at least one object, got an empty mapping");
  yaml.finish();
  return spec;
}

SegmentationSpec load_segmentation_spec(const std::filesystem::path& path) {
  std::ifstream in = open_input_file(path, "segmentation spec");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path.string(), 0, "", "read error");
  return parse_segmentation_spec(text.str(), path.string());
}

}  // namespace opf::vision
