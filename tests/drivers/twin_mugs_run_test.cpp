#include "drivers/experiment_run.h"

#include "bundled_experiment.h"
#include "drivers/observe_experiment.h"
#include "drivers/results_files.h"

#include "opf/core/pose_conversion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

namespace opf::experiments {
namespace {

// The tie, rendered: two mugs close in on the ball from either side at the same speed and hide
// it between them (~1.9 s), mug B slides over it and carries it 0.25 m away while mug A backs
// off, and mug B slides off it at ~5 s. 1000 + 1000 particles, three seeds, the experiment's own
// settings.
class TwinMugs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    config_ = bundled_experiment("twin_mugs");
    observation_ = observe_experiment(config_);
  }
  static ExperimentResults run(const EstimatorSettings& settings) {
    return run_open_loop(config_, observation_, {"opf"}, settings, 3, 5);
  }
  static EstimatorSettings settings() { return default_settings(config_, 1000); }
  static inline sim::ExperimentConfig config_;
  static inline Observation observation_;
};

// The mean error of the ball's hypothesis that `mug` carries (the main one or a further one), over
// the hidden frames in [from, to) of every seed.
double carried_by(const ExperimentResults& r, const std::string& mug, int from, int to) {
  double sum = 0.0;
  std::size_t frames = 0;
  for (const FrameRecord& record : r.records) {
    if (record.estimate.object != "ball" || record.visible || record.frame < from ||
        record.frame >= to || record.estimate.mode != EstimateMode::kCarried ||
        record.estimate.motion_model != mug)
      continue;
    sum += (translation_of(record.estimate.pose.mean) - record.truth.position).norm();
    ++frames;
  }
  EXPECT_GT(frames, 0u) << mug;
  return frames ? sum / double(frames) : 0.0;
}

TEST_F(TwinMugs, OneHypothesisFollowsEachMugAndTheRightOneSurvivesTheReveal) {
  const ExperimentResults r = run(settings());
  const HypothesisStats h = hypothesis_stats(r, "opf");
  ASSERT_GT(h.hidden_frames, 150u);
  // At onset (the mugs' rims 4.5 cm either side, the ball on the edge of either's silhouette):
  // left where it vanished at 2/3 (the prior odds 2:1), and carried by either mug, the third
  // shared by how likely each hides it; the onset frame's own evidence, at the detector's noise,
  // moves them by a few percent (3.3% at most in these seeds).
  std::map<std::size_t, std::map<std::string, double>> onset;  // seed -> hypothesis -> probability
  for (const FrameRecord& record : r.records) {
    if (record.frame != 60 || record.estimate.object != "ball") continue;
    const bool left = record.estimate.mode == EstimateMode::kLeft;
    onset[record.seed_index][left ? "left" : record.estimate.motion_model] +=
        record.estimate.probability;
  }
  ASSERT_EQ(onset.size(), 3u);
  for (auto& [seed, p] : onset) {
    EXPECT_NEAR(p["left"], 2.0 / 3.0, 0.035) << seed;
    EXPECT_NEAR(p["mug_a"] + p["mug_b"], 1.0 / 3.0, 0.035) << seed;
    EXPECT_GT(std::min(p["mug_a"], p["mug_b"]), 0.05) << seed;
  }
  // The hypothesis following mug B is held while B closes in and slides over the ball, then
  // carried at its offset of B's closest approach: the estimates' few mm to ~1 cm. The
  // target for the tie: 15 mm.
  EXPECT_LT(h.nearest_hidden_translation, 0.015);
  // Mug A backs off with its hypothesis beside its rim, where the ball would be as much in view
  // as when it vanished, and the ball's old place comes into view as B carries it away: both are
  // seen empty and lose. From 4 s (frame 120) on mug B's hypothesis is the main estimate in every
  // seed. Before, the left one was, until B had carried the ball ~5 cm: ~10 of the 93 hidden
  // frames at up to 5.5 cm.
  for (const FrameRecord& record : r.records) {
    if (record.frame < 120 || record.visible || record.estimate.object != "ball" ||
        record.estimate.hypothesis != 0)
      continue;
    EXPECT_EQ(record.estimate.motion_model, "mug_b") << record.frame;
  }
  EXPECT_LT(h.main_hidden_translation, 0.025);
  // Seen again under mug B's last place: one hypothesis is left, on the ball.
  for (const FrameRecord& record : r.records) {
    if (record.frame < config_.frames - 30) continue;
    EXPECT_EQ(record.estimate.hypothesis, 0) << record.frame;
    if (record.estimate.object != "ball") continue;
    EXPECT_LT((translation_of(record.estimate.pose.mean) - record.truth.position).norm(), 0.01)
        << record.frame;
  }
}

TEST_F(TwinMugs, CarriedFromOnsetTheBallsMugIsFollowedAtItsCentre) {
  // Until mug B has slid over the ball (3 s, frame 90), its hypothesis waits at the ball's place
  // (7.6 mm off here); without waiting for the departure it takes B's centre from onset, 4.5-5.5 cm
  // beside the ball (37 mm here).
  EXPECT_LT(carried_by(run(settings()), "mug_b", 0, 90), 0.01);
  EstimatorSettings s = settings();
  s.opf.occluder.carry_from_departure = false;
  EXPECT_GT(carried_by(run(s), "mug_b", 0, 90), 0.03);
}

}  // namespace
}  // namespace opf::experiments
