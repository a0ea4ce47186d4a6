// One full filter step per estimator (predict, measurement or OP update, normalise, resample,
// estimate) over particle counts 100 ... 100 000 per portion, reported as particles per second
// (both portions: 2N per step) so the cost curve over N is visible; the OPF's step while the
// object is hidden (moved and spread by the dynamics module's prediction), or hidden under a hand
// (carried or left); and the CV and IMM Kalman filters, which have no particles.

#include "opf/core/pose_conversion.h"
#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/estimators/cv_kalman.h"
#include "opf/estimators/imm_kalman.h"
#include "opf/estimators/object_permanence_filter.h"
#include "opf/estimators/registry.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

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

EstimatorSettings with_particles(std::size_t n) {
  EstimatorSettings settings;
  settings.pf.translation_particles = settings.pf.rotation_particles = n;
  return settings;
}

// A step with a measurement, through the registry as `opf track` builds it.
void BM_EstimatorStep(benchmark::State& state, const std::string& name) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::unique_ptr<Estimator> estimator =
      make_estimator_factory(name, with_particles(n))("object", 7);
  const auto stream = measurements(256);
  estimator->initialise(0.0, stream[0]);
  std::size_t k = 1;
  double t = 0.0;
  for (auto _ : state) {
    t += kDt;
    benchmark::DoNotOptimize(estimator->step(t, &stream[k++ % stream.size()], empty_ensemble()));
  }
  state.SetItemsProcessed(state.iterations() * 2 * state.range(0));
}

// Beside the mean and median, the fastest repetition: on a VM whose host is busy some of the time
// (docs/performance.md) it tells what the step costs when the CPU is the program's own.
void particle_counts(benchmark::internal::Benchmark* b) {
  b->ArgName("n")->RangeMultiplier(10)->Range(100, 100000)->Arg(3000)->Arg(5000)->Arg(30000);
  b->Unit(benchmark::kMicrosecond);
  b->ComputeStatistics("min", [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
  });
}

BENCHMARK_CAPTURE(BM_EstimatorStep, opf, std::string("opf"))->Apply(particle_counts);
BENCHMARK_CAPTURE(BM_EstimatorStep, pf, std::string("pf"))->Apply(particle_counts);
BENCHMARK_CAPTURE(BM_EstimatorStep, oapf, std::string("oapf"))->Apply(particle_counts);

// An OPF step while the object is hidden: every particle moved by its bank member's predicted
// motion and spread by the growth of its variance (permanence/mixture_particle_motion.h).
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
BENCHMARK(BM_OpfHiddenStep)->Apply(particle_counts);

// A hand (or tray) 12 cm above the table, seen at `x` with a 3 mm estimate.
struct HandAbove {
  Frame frame;
  std::vector<Estimate> previous;
  explicit HandAbove(double x) {
    const mrpt::poses::CPose3D pose = make_pose({x, 0.0, 0.12}, Eigen::Quaterniond::Identity());
    frame.detections.push_back({"hand", pose});
    Estimate estimate;
    estimate.object = "hand";
    estimate.pose.mean = pose;
    estimate.pose.cov.setDiagonal(1e-5);
    previous.push_back(estimate);
  }
  EnsembleView view() const { return {frame, previous}; }
};

// An OPF step while a still ball is hidden under a still hand: two hypotheses, left and carried
// by the hand, each stepped, then weighed by what the camera does not see (both places covered,
// so both live on). The counter `hypotheses` says how many there were at the end.
void BM_OpfCarriedOrLeftStep(benchmark::State& state) {
  OpfOptions options;
  options.particles.translation_particles = options.particles.rotation_particles =
      std::size_t(state.range(0));
  ObjectPermanenceFilter opf(options, "ball", 7);
  const mrpt::poses::CPose3D ball = make_pose({0.4, 0.0, 0.02}, Eigen::Quaterniond::Identity());
  const HandAbove beside(0.48), over(0.4);  // last seen with the hand 8 cm away, then under it
  opf.initialise(0.0, ball);
  double t = 0.0;
  for (int k = 1; k < 60; ++k) opf.step(t += kDt, &ball, beside.view());
  opf.step(t += kDt, nullptr, beside.view());
  for (auto _ : state) benchmark::DoNotOptimize(opf.step(t += kDt, nullptr, over.view()));
  state.counters["hypotheses"] = double(1 + opf.extra_hypotheses().size());
  state.SetItemsProcessed(state.iterations() * 2 * state.range(0));
}
BENCHMARK(BM_OpfCarriedOrLeftStep)->Arg(5000)->ArgName("n")->Unit(benchmark::kMicrosecond);

// One step of a Kalman filter estimator per iteration, on a measured stream.
template <class Filter, class Options>
void kalman_steps(benchmark::State& state) {
  Filter filter{Options{}};
  const auto stream = measurements(256);
  filter.initialise(0.0, stream[0]);
  std::size_t k = 1;
  double t = 0.0;
  for (auto _ : state) {
    t += kDt;
    benchmark::DoNotOptimize(filter.step(t, &stream[k++ % stream.size()], empty_ensemble()));
  }
}

void BM_CvKalmanStep(benchmark::State& state) {
  kalman_steps<ConstantVelocityKalman, CvKalmanOptions>(state);
}
BENCHMARK(BM_CvKalmanStep)->Unit(benchmark::kMicrosecond);

// Three models per axis: mixing, three model-matched filters and the combination, per axis.
void BM_ImmStep(benchmark::State& state) {
  kalman_steps<ImmKalman, ImmOptions>(state);
}
BENCHMARK(BM_ImmStep)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace opf
