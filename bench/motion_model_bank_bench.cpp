// The motion-model banks for one object: the translation bank's per-frame update
// (permanence/motion_model_bank.h; 3 axes, every member's Kalman step and the weights: 15 + 15 +
// 18 members with the defaults), with clean views and with partial views, and its predictive
// mixture for one horizon (every member's prediction, as the particles of a gap would draw from
// it); the rotation bank's per-frame update (permanence/rotation_model_bank.h; 3 + 3 + 9 members).

#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/permanence/motion_model_bank.h"
#include "opf/permanence/rotation_model_bank.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace opf {
namespace {

constexpr double kDt = 1.0 / 30.0;

// A ball thrown across the view, measured with 2 mm noise at 30 Hz, generated up front.
std::vector<Eigen::Vector3d> throw_positions(std::size_t count) {
  Random noise(9);
  std::vector<Eigen::Vector3d> positions;
  for (std::size_t k = 0; k < count; ++k) {
    const double t = static_cast<double>(k) * kDt;
    positions.emplace_back(Eigen::Vector3d(0.4 + 1.0 * t, 0.5 * t, 0.1 + 3.0 * t - 4.905 * t * t) +
                           0.002 * Eigen::Vector3d(noise.normal(), noise.normal(), noise.normal()));
  }
  return positions;
}

// Every frame stating `extra_noise` (m; 0: none) is the worst case of a stretch of partial views,
// each member's update then a 3-state one (its bias s).
void run_updates(benchmark::State& state, double extra_noise) {
  const auto positions = throw_positions(256);
  MotionModelBank bank;
  std::size_t k = 0;
  double t = 0.0;
  for (auto _ : state) {
    bank.update(t, positions[k], extra_noise);
    t += kDt;
    k = (k + 1) % positions.size();
    benchmark::ClobberMemory();
  }
  state.counters["members"] =
      static_cast<double>(bank.members(0).size() + bank.members(1).size() + bank.members(2).size());
}

void BM_BankUpdate(benchmark::State& state) {
  run_updates(state, 0.0);
}
BENCHMARK(BM_BankUpdate)->Unit(benchmark::kMicrosecond);

void BM_BankUpdatePartialViews(benchmark::State& state) {
  run_updates(state, 0.005);
}
BENCHMARK(BM_BankUpdatePartialViews)->Unit(benchmark::kMicrosecond);

void BM_BankPredict(benchmark::State& state) {
  const auto positions = throw_positions(30);
  MotionModelBank bank;
  for (std::size_t k = 0; k < positions.size(); ++k)
    bank.update(static_cast<double>(k) * kDt, positions[k]);
  for (auto _ : state) {
    BankPrediction prediction = bank.predict(0.5);
    benchmark::DoNotOptimize(prediction);
  }
}
BENCHMARK(BM_BankPredict)->Unit(benchmark::kMicrosecond);

// A body turning at 1 rad/s about a tilted axis, measured with 0.01 rad noise at 30 Hz; the
// default bank (damped:1) and the bank without its damped model (damped:0).
void BM_RotationBankUpdate(benchmark::State& state) {
  Random noise(9);
  std::vector<Eigen::Quaterniond> orientations;
  for (std::size_t k = 0; k < 256; ++k) {
    const Eigen::Vector3d turn = static_cast<double>(k) * kDt * Eigen::Vector3d(0.6, 0.0, 0.8);
    const Eigen::Vector3d jitter(noise.normal(), noise.normal(), noise.normal());
    orientations.push_back(so3::exp(turn) * so3::exp(0.01 * jitter));
  }
  RotationModelBankOptions options;
  options.damped_angular_velocity = state.range(0) != 0;
  RotationModelBank bank(options);
  std::size_t k = 0;
  double t = 0.0;
  for (auto _ : state) {
    bank.update(t, orientations[k]);
    t += kDt;
    k = (k + 1) % orientations.size();
    benchmark::ClobberMemory();
  }
  state.counters["members"] = static_cast<double>(bank.members().size());
}
BENCHMARK(BM_RotationBankUpdate)->ArgName("damped")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// Both banks of one object per frame, as above, with a camera's clock: each frame's interval
// 1/30 s +- up to 1 ms (uniform, seeded), so no two steps share a dt.
void BM_BanksUpdateJitteredClock(benchmark::State& state) {
  const auto positions = throw_positions(256);
  Random noise(11);
  std::vector<double> times(positions.size());
  for (std::size_t k = 1; k < times.size(); ++k)
    times[k] = times[k - 1] + kDt + 0.002 * (noise.uniform() - 0.5);
  std::vector<Eigen::Quaterniond> orientations;
  for (const double t : times) orientations.push_back(so3::exp(t * Eigen::Vector3d(0.6, 0.0, 0.8)));
  const double period = times.back() + kDt;  // the clock runs on across the laps
  MotionModelBank translation;
  RotationModelBank rotation;
  std::size_t k = 0;
  double lap = 0.0;
  for (auto _ : state) {
    const double t = lap + times[k];
    translation.update(t, positions[k]);
    rotation.update(t, orientations[k]);
    if (++k == positions.size()) {
      k = 0;
      lap += period;
    }
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_BanksUpdateJitteredClock)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace opf
