// A long run of the OPF ensemble: 10^6 object-steps (8 objects, 125 000 frames at 30 Hz, about
// 70 minutes of tracking) with random occlusions, some of them minutes long (trace(Q~) reaches
// its cap), and occasional wildly wrong measurements (5 m off: every particle's weight
// underflows or the reset gate fires). Every estimate must stay finite, and the process's memory
// must not grow once the ensemble is running: a leak of more than one byte per object-step would
// show.

#include "opf/core/pose_conversion.h"
#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/core/tracker.h"
#include "opf/estimators/registry.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace opf {
namespace {

constexpr int kObjects = 8;
#if defined(__SANITIZE_ADDRESS__)
// A tenth of the run under the sanitizers (each step there costs about 30 times as much): the
// same mix of occlusions, cap and wrong measurements, in about half a minute.
constexpr int kFrames = 12'500;
#else
constexpr int kFrames = 125'000;
#endif
constexpr double kRate = 30.0;
// The counts below are stated for the whole run and scaled to kFrames.
constexpr double kShare = kFrames / 125'000.0;
std::size_t scaled(double count) {
  return static_cast<std::size_t>(kShare * count);
}

// Resident memory of this process, from /proc/self/statm.
std::size_t resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

bool finite(const Estimate& e) {
  if (!std::isfinite(e.observation_trace)) return false;
  for (const double v : e.pose.mean.asVectorVal())
    if (!std::isfinite(v)) return false;
  return e.pose.cov.asEigen().allFinite();
}

// Each object's visibility: a two-state chain (hidden about every 2 s for about 1 s), and one
// occlusion in fifty that lasts two minutes.
struct Visibility {
  bool hidden = false;
  int frames_left = 0;

  bool step(Random& random) {
    if (hidden) {
      hidden = --frames_left > 0;
    } else if (random.uniform() < 1.0 / (2.0 * kRate)) {
      hidden = true;
      frames_left = random.uniform() < 0.02 ? static_cast<int>(120 * kRate)
                                            : 1 + static_cast<int>(random.uniform() * 2 * kRate);
    }
    return !hidden;
  }
};

TEST(EnsembleSoak, AMillionObjectStepsStayFiniteInFlatMemory) {
  EstimatorSettings settings;
  settings.pf.translation_particles = settings.pf.rotation_particles = 100;
  Tracker tracker(make_estimator_factory("opf", settings), 11);
  Random random(23);
  std::vector<Visibility> visibility(kObjects);
  std::map<EstimateMode, std::size_t> modes;
  std::size_t resets = 0, capped = 0, underflows = 0;
  std::size_t estimates = 0, not_finite = 0, wrong_measurements = 0;
  std::size_t memory_after_warm_up = 0;
  double largest_trace = 0.0;
  for (int k = 0; k < kFrames; ++k) {
    Frame frame{k / kRate, {}};
    for (int i = 0; i < kObjects; ++i) {
      if (!visibility[i].step(random)) continue;
      // Circles of different radii and speeds, each object turning about z as it goes.
      const double a = (0.2 + 0.05 * i) * frame.t + i;
      Eigen::Vector3d p(0.5 + (0.1 + 0.02 * i) * std::cos(a), (0.1 + 0.02 * i) * std::sin(a),
                        0.01 * i);
      p += 0.002 * Eigen::Vector3d(random.normal(), random.normal(), random.normal());
      if (random.uniform() < 1.0 / 500.0) {
        p.x() += 5.0;
        ++wrong_measurements;
      }
      frame.detections.push_back(
          {"object" + std::to_string(i), make_pose(p, so3::exp(Eigen::Vector3d(0, 0, a)))});
    }
    for (const Estimate& e : tracker.step(frame)) {
      ++estimates;
      ++modes[e.mode];
      resets += e.recovery.sensor_reset;
      capped += e.recovery.trace_capped;
      underflows += e.recovery.weights_underflow;
      if (!finite(e)) ++not_finite;
      largest_trace = std::max(largest_trace, e.observation_trace);
    }
    for (const Estimate& e : tracker.hypotheses())
      if (!finite(e)) ++not_finite;
    if (k == kFrames / 10) memory_after_warm_up = resident_bytes();
  }
  const std::size_t memory_at_end = resident_bytes();
  std::printf(
      "modes: measured %zu, predicted %zu, dynamics %zu, occluder %zu; %zu wrong "
      "measurements; recoveries: %zu reset, %zu underflow, %zu capped; largest trace %g; "
      "resident %zu -> %zu bytes\n",
      modes[EstimateMode::kMeasured], modes[EstimateMode::kPredicted],
      modes[EstimateMode::kDynamics], modes[EstimateMode::kCarried], wrong_measurements, resets,
      underflows, capped, largest_trace, memory_after_warm_up, memory_at_end);

  EXPECT_EQ(estimates, static_cast<std::size_t>(kObjects) * kFrames);
  EXPECT_EQ(not_finite, 0u);
  // The run exercised what it is meant to: both OP modules, long occlusions up to the cap of
  // 10^6 Q (trace(Q) = 3 (0.01^2 + 0.05^2) = 0.0078), and wrong measurements.
  EXPECT_GT(modes[EstimateMode::kDynamics] + modes[EstimateMode::kCarried], scaled(100'000));
  // Visible about 2 s, then hidden about 1 s or (one time in fifty) 120 s: 2 / (2 + 3.4) of
  // the object-steps are measured, about 370 000.
  EXPECT_GT(modes[EstimateMode::kMeasured], scaled(300'000));
  EXPECT_GT(wrong_measurements, scaled(400));  // about 660 expected
  EXPECT_NEAR(largest_trace, 1e6 * 0.0078, 1e-6);
  // ... and reported them: each wrong measurement (5 m = 500 sigmas off) and the return to the
  // truth after it re-scatter the cloud. A cycle lasts 2 + 0.98 * 1 + 0.02 * 120 = 5.4 s on
  // average, so the 8 x 4167 s hold about 124 two-minute occlusions (Poisson, sd 11). The
  // variance of the motion-model banks' mixture grows with the time hidden (as h^3 for its
  // constant-velocity members) and reaches the cap of 10^6 Q within the first 90 s of each: over
  // 100 000 capped object-steps (the paper predictor's kappa^v inflation reaches it after 468
  // frames, 390 000 in all).
  EXPECT_GE(resets, wrong_measurements);
  EXPECT_GT(capped, scaled(100'000));
#if !defined(__SANITIZE_ADDRESS__)
  // Flat memory: under 1 MiB of growth over the last 900 000 object-steps (4 KiB when written).
  EXPECT_LE(memory_at_end, memory_after_warm_up + (std::size_t{1} << 20))
      << "resident " << memory_after_warm_up << " -> " << memory_at_end << " bytes";
#else
  // AddressSanitizer keeps freed blocks in quarantine and maps shadow memory, so resident memory
  // grows by design there; LeakSanitizer checks for leaks at exit instead.
  (void)memory_after_warm_up;
  (void)memory_at_end;
#endif
}

}  // namespace
}  // namespace opf
