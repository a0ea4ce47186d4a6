#include "opf/vision/segmentation_spec.h"

#include "opf/io/input_error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace opf::vision {
namespace {

/// The InputError parsing `yaml` must raise; fails the test (and returns an empty error) when none.
InputError error_of(const std::string& yaml) {
  try {
    parse_segmentation_spec(yaml, "spec.yaml");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << yaml;
  return InputError("", 0, "", "");
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(VisionSegmentationSpec, ReadsEveryKey) {
  const SegmentationSpec spec = parse_segmentation_spec(
      "objects:\n"
      "  box:\n"
      "    hsv: {low: [170, 100, 80], high: [10, 255, 250]}\n"
      "    morphology: {open: 5, close: 15}\n"
      "    fragments: {fraction: 0.2, distance: 40}\n"
      "    roi: [10, 20, 300, 200]\n"
      "    min_area: 3000\n"
      "    pose: {metres_per_pixel: 0.002, reference_depth: 0.8, reference_area: 25000,\n"
      "           reference_frames: 3}\n"
      "  walker:\n"
      "    background: {start: [250.5, 495], start_frame: 585, gate: 40, history: 300,\n"
      "                 var_threshold: 25, shadows: false, learning_rate: 0.01}\n"
      "  shadow:\n"
      "    dark: 60\n"
      "  paper:\n"
      "    light: 200\n",
      "spec.yaml");
  ASSERT_EQ(spec.objects.size(), 4u);
  const ObjectSpec& box = spec.objects[0];
  EXPECT_EQ(box.name, "box");
  EXPECT_EQ(box.segmentation.method, SegmentationMethod::kHsv);
  EXPECT_EQ(box.segmentation.hsv.low, (std::array<int, 3>{170, 100, 80}));
  EXPECT_EQ(box.segmentation.hsv.high, (std::array<int, 3>{10, 255, 250}));
  EXPECT_EQ(box.segmentation.open_px, 5);
  EXPECT_EQ(box.segmentation.close_px, 15);
  EXPECT_EQ(box.segmentation.fragment_fraction, 0.2);
  EXPECT_EQ(box.segmentation.fragment_distance_px, 40.0);
  EXPECT_EQ(box.segmentation.roi, cv::Rect(10, 20, 300, 200));
  EXPECT_EQ(box.segmentation.min_area_px, 3000.0);
  EXPECT_EQ(box.pose.metres_per_pixel, 0.002);
  EXPECT_EQ(box.pose.reference_depth, 0.8);
  ASSERT_TRUE(box.pose.reference_area.has_value());
  EXPECT_EQ(*box.pose.reference_area, 25000.0);
  EXPECT_EQ(box.pose.reference_frames, 3u);

  const ObjectSpec& walker = spec.objects[1];
  EXPECT_EQ(walker.name, "walker");
  EXPECT_EQ(walker.segmentation.method, SegmentationMethod::kBackground);
  const BackgroundOptions& b = walker.segmentation.background;
  EXPECT_EQ(b.start, cv::Point2d(250.5, 495.0));
  EXPECT_EQ(b.start_frame, 585u);
  EXPECT_EQ(b.gate_px, 40.0);
  EXPECT_EQ(b.history, 300);
  EXPECT_EQ(b.var_threshold, 25.0);
  EXPECT_FALSE(b.shadows);
  EXPECT_EQ(b.learning_rate, 0.01);

  EXPECT_EQ(spec.objects[2].segmentation.method, SegmentationMethod::kDark);
  EXPECT_EQ(spec.objects[2].segmentation.grey_threshold, 60);
  EXPECT_EQ(spec.objects[3].segmentation.method, SegmentationMethod::kLight);
  EXPECT_EQ(spec.objects[3].segmentation.grey_threshold, 200);
}

TEST(VisionSegmentationSpec, UnsetKeysKeepTheDefaults) {
  const SegmentationSpec spec = parse_segmentation_spec(
      "objects:\n  ball:\n    hsv: {low: [0, 0, 0], high: [179, 255, 255]}\n", "spec.yaml");
  ASSERT_EQ(spec.objects.size(), 1u);
  const SegmenterOptions defaults;
  const ObjectSpec& ball = spec.objects[0];
  EXPECT_EQ(ball.segmentation.open_px, defaults.open_px);
  EXPECT_EQ(ball.segmentation.close_px, defaults.close_px);
  EXPECT_EQ(ball.segmentation.fragment_fraction, defaults.fragment_fraction);
  EXPECT_EQ(ball.segmentation.fragment_distance_px, defaults.fragment_distance_px);
  EXPECT_TRUE(ball.segmentation.roi.empty());
  EXPECT_EQ(ball.segmentation.min_area_px, defaults.min_area_px);
  EXPECT_EQ(ball.pose.metres_per_pixel, 0.001);
  EXPECT_EQ(ball.pose.reference_depth, 1.0);
  EXPECT_FALSE(ball.pose.reference_area.has_value());
  EXPECT_EQ(ball.pose.reference_frames, 5u);
}

TEST(VisionSegmentationSpec, UnknownKeyNamesFileKeyAndSuggestion) {
  const InputError e = error_of(
      "objects:\n"
      "  box:\n"
      "    hsv: {low: [20, 100, 100], high: [35, 255, 255]}\n"
      "    min_aera: 300\n");
  EXPECT_EQ(e.file(), "spec.yaml");
  EXPECT_EQ(e.line(), 4u);
  EXPECT_EQ(e.field(), "objects.box.min_aera");
  EXPECT_TRUE(contains(e.message(), "unknown key")) << e.what();
  EXPECT_TRUE(contains(e.message(), "did you mean 'min_area'")) << e.what();
  EXPECT_TRUE(contains(e.what(), "spec.yaml:4:")) << e.what();

  const InputError nested =
      error_of("objects:\n  box:\n    hsv: {low: [20, 100, 100], high: [35, 255, 255], hue: 3}\n");
  EXPECT_EQ(nested.field(), "objects.box.hsv.hue");
  const InputError top = error_of("object:\n  box:\n    dark: 3\n");
  EXPECT_EQ(top.field(), "objects");  // the missing key, not the misspelt one, comes first
  EXPECT_TRUE(contains(top.message(), "missing")) << top.what();
}

TEST(VisionSegmentationSpec, BadHsvRangesNameTheKeyAndTheValue) {
  const InputError hue =
      error_of("objects:\n  box:\n    hsv: {low: [200, 100, 100], high: [35, 255, 255]}\n");
  EXPECT_EQ(hue.file(), "spec.yaml");
  EXPECT_EQ(hue.field(), "objects.box.hsv.low");
  EXPECT_TRUE(contains(hue.message(), "h in 0..179")) << hue.what();
  EXPECT_TRUE(contains(hue.message(), "got [200, 100, 100]")) << hue.what();

  const InputError fraction =
      error_of("objects:\n  box:\n    hsv: {low: [20, 100.5, 100], high: [35, 255, 255]}\n");
  EXPECT_EQ(fraction.field(), "objects.box.hsv.low");
  EXPECT_TRUE(contains(fraction.message(), "whole numbers")) << fraction.what();

  const InputError order =
      error_of("objects:\n  box:\n    hsv: {low: [20, 200, 100], high: [35, 100, 255]}\n");
  EXPECT_EQ(order.field(), "objects.box.hsv.high");
  EXPECT_TRUE(contains(order.message(), "at least those of low [20, 200, 100]")) << order.what();

  const InputError length =
      error_of("objects:\n  box:\n    hsv: {low: [20, 100], high: [35, 255, 255]}\n");
  EXPECT_EQ(length.field(), "objects.box.hsv.low");
  EXPECT_TRUE(contains(length.message(), "a sequence of 3 numbers")) << length.what();

  const InputError missing = error_of("objects:\n  box:\n    hsv: {low: [20, 100, 100]}\n");
  EXPECT_EQ(missing.field(), "objects.box.hsv.high");
  EXPECT_TRUE(contains(missing.message(), "missing")) << missing.what();
}

TEST(VisionSegmentationSpec, ExactlyOneSegmentationPerObject) {
  const InputError none = error_of("objects:\n  box:\n    min_area: 30\n");
  EXPECT_EQ(none.field(), "objects.box");
  EXPECT_EQ(none.line(), 2u);
  EXPECT_TRUE(contains(none.message(), "hsv, dark, light or background")) << none.what();
  const InputError two = error_of("objects:\n  box:\n    dark: 30\n    light: 200\n");
  EXPECT_EQ(two.field(), "objects.box.light");
  EXPECT_TRUE(contains(two.message(), "not both 'dark' and 'light'")) << two.what();
}

TEST(VisionSegmentationSpec, OtherValuesOutOfRange) {
  const auto field_of = [](const std::string& object_yaml) {
    return error_of("objects:\n  o:\n" + object_yaml).field();
  };
  EXPECT_EQ(field_of("    dark: 256\n"), "objects.o.dark");
  EXPECT_EQ(field_of("    light: -1\n"), "objects.o.light");
  EXPECT_EQ(field_of("    dark: 9\n    roi: [0, 0, 0, 10]\n"), "objects.o.roi");
  EXPECT_EQ(field_of("    dark: 9\n    roi: [-1, 0, 5, 10]\n"), "objects.o.roi");
  EXPECT_EQ(field_of("    dark: 9\n    fragments: {fraction: 1.5}\n"),
            "objects.o.fragments.fraction");
  EXPECT_EQ(field_of("    dark: 9\n    morphology: {open: 300}\n"), "objects.o.morphology.open");
  EXPECT_EQ(field_of("    dark: 9\n    min_area: -3\n"), "objects.o.min_area");
  EXPECT_EQ(field_of("    dark: 9\n    pose: {reference_depth: 0}\n"),
            "objects.o.pose.reference_depth");
  EXPECT_EQ(field_of("    background: {gate: 4}\n"), "objects.o.background.start");
  EXPECT_EQ(field_of("    background: {start: [1, 2], learning_rate: 2}\n"),
            "objects.o.background.learning_rate");
  EXPECT_EQ(field_of("    background: {start: [1, 2], gate: 0}\n"), "objects.o.background.gate");
  EXPECT_TRUE(contains(error_of("objects: {}\n").message(), "at least one object"));
  EXPECT_TRUE(contains(error_of("objects: [a, b]\n").message(), "expected a mapping"));
  EXPECT_EQ(error_of("objects:\n  o: {dark: 3}\n  o: {dark: 4}\n").field(), "objects.o");
}

TEST(VisionSegmentationSpec, LoadNamesAMissingFile) {
  try {
    load_segmentation_spec("/nonexistent/spec.yaml");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/spec.yaml");
  }
}

TEST(VisionSegmentationSpec, TheBundledRealVideoSpecsLoad) {
  const std::filesystem::path dir =
      std::filesystem::path(OPF_SOURCE_DIR) / "experiments/real_video";
  const SegmentationSpec box = load_segmentation_spec(dir / "box.yaml");
  ASSERT_EQ(box.objects.size(), 1u);
  EXPECT_EQ(box.objects[0].segmentation.method, SegmentationMethod::kHsv);
  const SegmentationSpec vtest = load_segmentation_spec(dir / "vtest.yaml");
  ASSERT_EQ(vtest.objects.size(), 1u);
  EXPECT_EQ(vtest.objects[0].segmentation.method, SegmentationMethod::kBackground);
}

}  // namespace
}  // namespace opf::vision
