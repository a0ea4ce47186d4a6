// The Tracker's results do not depend on how many threads step the objects: every estimator
// reads the same previous-frame view and owns its generators.

#include "opf/core/pose_conversion.h"
#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/core/tracker.h"
#include "opf/estimators/registry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace opf {
namespace {

// Six objects on circles; objects 1 and 4 vanish for stretches (the OPF's occluder and dynamics
// modules run), object 5 appears late.
std::vector<Frame> ensemble_frames() {
  Random noise(17);
  std::vector<Frame> frames;
  for (int k = 0; k < 90; ++k) {
    Frame frame{k / 30.0, {}};
    for (int i = 0; i < 6; ++i) {
      if ((i == 1 && k > 30 && k < 55) || (i == 4 && k % 20 > 12) || (i == 5 && k < 10)) continue;
      const double a = 0.5 * frame.t + i;
      const Eigen::Vector3d p(0.3 * std::cos(a) + 0.1 * i, 0.3 * std::sin(a), 0.02 * i);
      const Eigen::Vector3d n(noise.normal(), noise.normal(), noise.normal());
      frame.detections.push_back({"object" + std::to_string(i),
                                  make_pose(p + 0.002 * n, so3::exp(Eigen::Vector3d(0, 0, a)))});
    }
    frames.push_back(std::move(frame));
  }
  return frames;
}

std::vector<Estimate> run(const std::string& estimator, std::size_t threads) {
  EstimatorSettings settings;
  settings.pf.translation_particles = settings.pf.rotation_particles = 500;
  Tracker tracker(make_estimator_factory(estimator, settings), 5, threads);
  std::vector<Estimate> all;
  for (const Frame& frame : ensemble_frames()) {
    for (const Estimate& e : tracker.step(frame)) all.push_back(e);
    for (const Estimate& e : tracker.hypotheses()) all.push_back(e);
  }
  return all;
}

void expect_identical(const std::vector<Estimate>& a, const std::vector<Estimate>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].object, b[i].object) << i;
    EXPECT_EQ(a[i].t, b[i].t) << i;
    EXPECT_EQ(a[i].mode, b[i].mode) << i;
    EXPECT_EQ(a[i].hypothesis, b[i].hypothesis) << i;
    EXPECT_EQ(a[i].observation_trace, b[i].observation_trace) << i;
    EXPECT_EQ(a[i].pose.mean.asVectorVal(), b[i].pose.mean.asVectorVal()) << i;
    EXPECT_EQ(a[i].pose.cov.asEigen(), b[i].pose.cov.asEigen()) << i;
  }
}

TEST(TrackerThreads, OpfEnsembleIsBitIdenticalForAnyThreadCount) {
  const std::vector<Estimate> one = run("opf", 1);
  expect_identical(one, run("opf", 2));
  expect_identical(one, run("opf", 4));
}

TEST(TrackerThreads, OtherEstimatorsToo) {
  for (const char* name : {"pf", "oapf", "cvkf", "imm"})
    expect_identical(run(name, 1), run(name, 3));
}

}  // namespace
}  // namespace opf
