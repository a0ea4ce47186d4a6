// One full filter step per estimator (predict, measurement update, normalise, resample) over
// particle counts, reported as particles per second so the cost curve over N is visible.

#include "core/pose_conversion.h"
#include "core/so3.h"
#include "estimators/cv_kalman.h"
#include "estimators/object_permanence_filter.h"
#include "estimators/standard_pf.h"
#include "particles/random.h"

#include <benchmark/benchmark.h>

namespace opf {
namespace {

constexpr double kDt = 1.0 / 30.0;

// A measurement stream of a slowly moving, turning object with 5 mm / 0.02 rad noise, generated
// up front so the benchmark times the filter only.
std::vector<mrpt::poses::CPose3D> measurements(std::size_t count) {
  Random noise(1);
  std::vector<mrpt::poses::CPose3D> stream;
  for (std::size_t k = 0; k < count; ++k) {
    const double t = static_cast<double>(k) * kDt;
    const Eigen::Vector3d p(0.4 + 0.005 * noise.normal(), 0.08 * t + 0.005 * noise.normal(), 0.02);
    const Eigen::Quaterniond q = so3::exp(Eigen::Vector3d(0, 0, 0.5 * t + 0.02 * noise.normal()));
    stream.push_back(make_pose(p, q));
  }
  return stream;
}

const EnsembleView& empty_ensemble() {
  static const Frame frame;
  static const EnsembleView view{frame, {}};
  return view;
}

void BM_StandardPfStep(benchmark::State& state) {
  PoseParticleFilterOptions options;
  options.translation_particles = options.rotation_particles = std::size_t(state.range(0));
  StandardParticleFilter pf(options, 7);
  const auto stream = measurements(256);
  pf.initialise(0.0, stream[0]);
  std::size_t k = 1;
  double t = 0.0;
  for (auto _ : state) {
    t += kDt;
    benchmark::DoNotOptimize(pf.step(t, &stream[k++ % stream.size()], empty_ensemble()));
  }
  // Both portions: 2N particles per step.
  state.SetItemsProcessed(state.iterations() * 2 * state.range(0));
}
BENCHMARK(BM_StandardPfStep)
    ->RangeMultiplier(10)
    ->Range(100, 100000)
    ->Arg(5000)
    ->Unit(benchmark::kMicrosecond);

// An OPF step while the object is hidden: predict, carry along the fitted trajectory, update
// with the virtual measurement under the inflated Q~, resample. The fit itself happens once at
// occlusion onset, before the timed loop (see trajectory_fit_bench.cpp for its cost).
void BM_OpfHiddenStep(benchmark::State& state) {
  OpfOptions options;
  options.particles.translation_particles = options.particles.rotation_particles =
      std::size_t(state.range(0));
  ObjectPermanenceFilter opf(options, "ball", 7);
  const auto stream = measurements(60);
  opf.initialise(0.0, stream[0]);
  double t = 0.0;
  for (std::size_t k = 1; k < stream.size(); ++k) opf.step(t += kDt, &stream[k], empty_ensemble());
  for (auto _ : state) benchmark::DoNotOptimize(opf.step(t += kDt, nullptr, empty_ensemble()));
  state.SetItemsProcessed(state.iterations() * 2 * state.range(0));
}
BENCHMARK(BM_OpfHiddenStep)->Arg(1000)->Arg(5000)->Unit(benchmark::kMicrosecond);

void BM_CvKalmanStep(benchmark::State& state) {
  ConstantVelocityKalman kf(CvKalmanOptions{});
  const auto stream = measurements(256);
  kf.initialise(0.0, stream[0]);
  std::size_t k = 1;
  double t = 0.0;
  for (auto _ : state) {
    t += kDt;
    benchmark::DoNotOptimize(kf.step(t, &stream[k++ % stream.size()], empty_ensemble()));
  }
}
BENCHMARK(BM_CvKalmanStep)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace opf
