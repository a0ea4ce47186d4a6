// The ensemble: one frame of K objects (each with its OPF at 5000 + 5000 particles, every object
// measured, as in a cluttered scene before any occlusion) stepped by the Tracker on one thread
// and on two. A frame's time is what a camera-rate loop must fit in; items are object-steps.

#include "opf/core/pose_conversion.h"
#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/core/tracker.h"
#include "opf/estimators/registry.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

namespace opf {
namespace {

// K objects on a grid, each drifting on its own small circle, with 5 mm / 0.02 rad noise.
std::vector<Frame> frames(std::size_t objects, std::size_t count) {
  Random noise(2);
  std::vector<Frame> out;
  for (std::size_t k = 0; k < count; ++k) {
    Frame frame{static_cast<double>(k) / 30.0, {}};
    for (std::size_t i = 0; i < objects; ++i) {
      const double a = 0.5 * frame.t + static_cast<double>(i);
      const Eigen::Vector3d p(0.1 * static_cast<double>(i % 8) + 0.02 * std::cos(a),
                              0.1 * static_cast<double>(i / 8) + 0.02 * std::sin(a), 0.02);
      const Eigen::Vector3d n(noise.normal(), noise.normal(), noise.normal());
      frame.detections.push_back(
          {"object" + std::to_string(i),
           make_pose(p + 0.005 * n, so3::exp(Eigen::Vector3d(0, 0, a + 0.02 * noise.normal())))});
    }
    out.push_back(std::move(frame));
  }
  return out;
}

void BM_EnsembleFrame(benchmark::State& state) {
  const auto objects = static_cast<std::size_t>(state.range(0));
  const auto threads = static_cast<std::size_t>(state.range(1));
  Tracker tracker(make_estimator_factory("opf", EstimatorSettings{}), 3, threads);
  const std::vector<Frame> stream = frames(objects, 64);
  tracker.step(stream[0]);  // creates the estimators
  std::size_t k = 1;
  double t0 = stream.back().t;
  for (auto _ : state) {
    Frame frame = stream[k % stream.size()];
    frame.t = t0 + static_cast<double>(k++) / 30.0;  // time keeps increasing as the loop wraps
    benchmark::DoNotOptimize(tracker.step(frame).data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_EnsembleFrame)
    ->ArgNames({"objects", "threads"})
    ->ArgsProduct({{1, 2, 4, 8, 16, 32, 64, 128}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();  // wall time: the CPU time of the caller's thread misses the worker's

}  // namespace
}  // namespace opf
