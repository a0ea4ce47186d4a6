// The dynamics module's fit at occlusion onset: a Huber fit of H = 50 samples (100 Hz, 2 mm /
// 0.01 rad noise) per translation order and rotation case. It runs once per occlusion, not per
// frame, so tens to hundreds of microseconds are affordable.

#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/fit/trajectory_fit.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace opf {
namespace {

enum RotationCase : int {
  kExactlyStill = 0,    // the rotation problem starts at its optimum: translation cost only
  kSpinning = 1,        // 0.8 rad/s about a tilted axis, with noise
  kStillWithNoise = 2,  // a sliding object: the axis is unobservable, the slowest case
};

// Linear motion for order 1, a throw for order 2: each order on the motion it is meant for.
std::vector<TrajectorySample> history(int translation_order, RotationCase rotation) {
  Random noise(3);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const Eigen::Quaterniond start = so3::exp(Eigen::Vector3d(0.2, 0.4, -1.1));
  std::vector<TrajectorySample> samples;
  for (int k = 0; k < 50; ++k) {
    const double t = k / 100.0;
    TrajectorySample s;
    s.t = t;
    const double fall = translation_order >= 2 ? 4.905 * t * t : 0.0;
    s.position = Eigen::Vector3d(0.4 + 1.0 * t, 0.5 * t, 0.1 + 3.0 * t - fall);
    for (int i = 0; i < 3; ++i) s.position(i) += 0.002 * noise.normal();
    const Eigen::Vector3d jitter(noise.normal(), noise.normal(), noise.normal());
    s.orientation = start;
    if (rotation == kSpinning) s.orientation = start * so3::exp(0.8 * t * axis);
    if (rotation != kExactlyStill) s.orientation = s.orientation * so3::exp(0.01 * jitter);
    samples.push_back(s);
  }
  return samples;
}

void BM_FitTrajectory(benchmark::State& state) {
  TrajectoryFitOptions options;  // Huber
  options.translation_order = static_cast<int>(state.range(0));
  const auto samples =
      history(options.translation_order, static_cast<RotationCase>(state.range(1)));
  int iterations = 0;
  for (auto _ : state) {
    const TrajectoryModel model = fit_trajectory(samples, options);
    iterations = model.translation_summary().iterations + model.rotation_summary().iterations;
    benchmark::DoNotOptimize(model);
  }
  state.counters["solver_iterations"] = iterations;
}
BENCHMARK(BM_FitTrajectory)
    ->ArgNames({"translation_order", "rotation"})
    ->ArgsProduct({{1, 2}, {kExactlyStill, kSpinning, kStillWithNoise}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace opf
