// The default dynamics module's model choice at occlusion onset (permanence/motion_prediction.h):
// every model and window scored by rolling-origin validation, then combined. It runs once per
// occlusion, not per frame; the target is 1 ms at the default 2 s of history. Measured per frame
// rate, since the history's length in samples (and so the cost) grows with it.

#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/permanence/motion_prediction.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace opf {
namespace {

// A ball thrown and spinning, measured with 2 mm / 0.01 rad noise for `seconds` at `rate` Hz.
std::vector<MotionSample> history(double rate, double seconds) {
  Random noise(5);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  std::vector<MotionSample> samples;
  const int count = static_cast<int>(seconds * rate) + 1;
  for (int k = 0; k < count; ++k) {
    const double t = k / rate;
    MotionSample s;
    s.t = t;
    s.estimated_position = Eigen::Vector3d(0.4 + 1.0 * t, 0.5 * t, 0.1 + 3.0 * t - 4.905 * t * t);
    s.estimated_orientation = so3::exp(0.8 * t * axis);
    s.measured_position = s.estimated_position +
                          0.002 * Eigen::Vector3d(noise.normal(), noise.normal(), noise.normal());
    s.measured_orientation =
        s.estimated_orientation *
        so3::exp(0.01 * Eigen::Vector3d(noise.normal(), noise.normal(), noise.normal()));
    samples.push_back(s);
  }
  return samples;
}

// Second argument: the wandering velocity's filters on (the default) or off, to see their cost.
void BM_PredictMotion(benchmark::State& state) {
  const auto samples = history(static_cast<double>(state.range(0)), 2.0);
  MotionPredictionOptions options;
  options.wandering_velocity = state.range(1) != 0;
  for (auto _ : state) {
    auto prediction = predict_motion(samples, options);
    benchmark::DoNotOptimize(prediction);
  }
  state.counters["samples"] = static_cast<double>(samples.size());
}
BENCHMARK(BM_PredictMotion)
    ->ArgNames({"rate_hz", "wandering"})
    ->ArgsProduct({{10, 30, 100}, {1, 0}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace opf
