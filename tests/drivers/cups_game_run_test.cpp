#include "drivers/experiment_run.h"

#include "bundled_experiment.h"
#include "drivers/observe_experiment.h"
#include "drivers/results_files.h"

#include "opf/core/pose_conversion.h"
#include "opf/permanence/hypothesis_probabilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace opf::experiments {
namespace {

// The cups game, seeded: 1000 + 1000 particles, one seed, the default settings. The ball
// is hidden from ~1.5 s until cup B is lifted at ~8.2 s while B travels ~0.6 m through two swaps.
TEST(CupsGame, TheOpfFollowsTheBallsCupThroughTheShuffle) {
  const sim::ExperimentConfig config = bundled_experiment("cups_game");
  const Observation observation = observe_experiment(config);
  const EstimatorSettings settings = default_settings(config, 1000);
  const ExperimentResults r = run_open_loop(config, observation, {"opf", "pf"}, settings, 1, 9);
  const RunErrors& pf = r.runs.at("pf")[0];
  // The PF keeps the ball where it vanished, ~0.18 m from it on average while hidden. The OPF
  // keeps a hypothesis per plausible carrier (cup B, the hand over it) and one left in place;
  // the nearest follows the ball across the line of sight at its own depth: what remains is the
  // x-y offset taken at onset, while the cup still slides over the ball, and the lag of the
  // carrier's filtered estimate through the swaps (7 mm here; the target: 15 mm). The main
  // one is the hand's until the hand lets go of cup B and the place under it is seen empty, then
  // cup B's (docs/occluder.md).
  EXPECT_GT(pf.translation_unobserved, 0.15);
  EXPECT_LT(hypothesis_stats(r, "opf").nearest_hidden_translation, 0.015);
  // In no frame is another hypothesis substantially more probable than the main one (a Bayes
  // factor of sqrt(10)), whichever of the others it is: the ball's carriers are three and the
  // left place one more.
  std::map<int, double> main, best_other;
  for (const FrameRecord& record : r.records) {
    if (record.estimator != "opf" || record.estimate.object != "ball") continue;
    const double p = record.estimate.probability;
    if (record.estimate.hypothesis == 0)
      main[record.frame] = p;
    else
      best_other[record.frame] = std::max(best_other[record.frame], p);
  }
  EXPECT_GT(best_other.size(), 100u);
  for (const auto& [frame, p] : best_other)
    EXPECT_LT(p, kSubstantialBayesFactor * main.at(frame)) << "frame " << frame;
  // Once the ball is seen again, both end on it.
  for (const FrameRecord& record : r.records) {
    if (record.frame != config.frames - 1 || record.estimate.object != "ball" ||
        record.estimate.hypothesis != 0)
      continue;
    EXPECT_LT((translation_of(record.estimate.pose.mean) - record.truth.position).norm(), 0.01)
        << record.estimator;
  }
}

}  // namespace
}  // namespace opf::experiments
