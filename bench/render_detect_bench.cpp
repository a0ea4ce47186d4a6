// The simulated camera's per-frame cost at 640x480: rendering a 5-body scene (the paper's first
// experiment: table, ball, two mugs, tray) headless through MRPT/EGL, detecting the tracked
// bodies' colour blobs, and both together (target: within 10 ms a frame).

#include <benchmark/benchmark.h>

#include <cmath>

#include "opf/sim/colour_blob_detector.h"
#include "opf/sim/scene_renderer.h"

namespace opf::sim {
namespace {

SceneSnapshot paper_scene() {
  SceneSnapshot scene;
  scene.bodies = {
      make_body("table", Shape::kBox, Eigen::Vector3d(1.2, 1.2, 0.04), palette::kTable, false),
      make_body("ball", Shape::kSphere, Eigen::Vector3d::Constant(0.025), palette::kBall, true),
      make_body("left_mug", Shape::kCylinder, Eigen::Vector3d(0.04, 0.04, 0.1), palette::kLeftMug,
                true),
      make_body("right_mug", Shape::kCylinder, Eigen::Vector3d(0.04, 0.04, 0.1), palette::kRightMug,
                true),
      make_body("tray", Shape::kBox, Eigen::Vector3d(0.2, 0.12, 0.02), palette::kTray, true)};
  scene.poses = {pose_at({0.55, 0.0, -0.02}), pose_at({0.4, 0.0, 0.025}),
                 pose_at({0.4, 0.15, 0.05}), pose_at({0.4, -0.15, 0.05}),
                 pose_at({0.55, -0.09, 0.2})};
  return scene;
}

// Moves the ball and mugs a little every frame, as the experiments do, so no frame is a pure
// repeat of the last.
void advance(SceneSnapshot& scene, int frame) {
  const double phase = 0.05 * frame;
  scene.poses[1].position.y() = 0.1 * std::sin(phase);
  scene.poses[2].position.x() = 0.4 + 0.05 * std::sin(phase);
  scene.poses[3].position.x() = 0.4 - 0.05 * std::sin(phase);
}

CameraModel paper_camera() {
  return CameraModel::top_down(Eigen::Vector3d(0.55, 0.0, 0.49));
}

// Each benchmark owns the process's one renderer while it runs (MRPT allows one at a time); its
// creation and first frame (shader compilation) are outside the timed loop.
void BM_RenderFrame(benchmark::State& state) {
  SceneRenderer renderer(paper_camera());
  SceneSnapshot scene = paper_scene();
  RgbdFrame frame;
  renderer.render(scene, frame);
  int k = 0;
  for (auto _ : state) {
    advance(scene, ++k);
    renderer.render(scene, frame);
    benchmark::DoNotOptimize(frame.depth.data);
  }
}
BENCHMARK(BM_RenderFrame)->Unit(benchmark::kMillisecond);

void BM_DetectFrame(benchmark::State& state) {
  SceneSnapshot scene = paper_scene();
  RgbdFrame frame;
  {
    SceneRenderer renderer(paper_camera());
    renderer.render(scene, frame);
  }
  const CameraModel camera = paper_camera();
  ColourBlobDetector detector;
  for (auto _ : state) {
    benchmark::DoNotOptimize(detector.detect_tracked(frame.bgr, frame.depth, scene.bodies, camera));
  }
}
BENCHMARK(BM_DetectFrame)->Unit(benchmark::kMillisecond);

void BM_RenderAndDetectFrame(benchmark::State& state) {
  SceneRenderer renderer(paper_camera());
  ColourBlobDetector detector;
  SceneSnapshot scene = paper_scene();
  RgbdFrame frame;
  renderer.render(scene, frame);
  int k = 0;
  for (auto _ : state) {
    advance(scene, ++k);
    renderer.render(scene, frame);
    benchmark::DoNotOptimize(
        detector.detect_tracked(frame.bgr, frame.depth, scene.bodies, renderer.camera()));
  }
}
BENCHMARK(BM_RenderAndDetectFrame)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace opf::sim
