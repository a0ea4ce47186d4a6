#include "drivers/experiment_run.h"

#include "drivers/observe_experiment.h"
#include "drivers/results_files.h"
#include "opf/io/estimator_settings_yaml.h"

#include "opf/core/pose_conversion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

namespace opf::experiments {
namespace {

// The tie, rendered: two mugs close in on the ball from either side at the same speed and hide
// it between them (~1.9 s), mug B slides over it and carries it 0.25 m away while mug A backs
// off, and mug B slides off it at ~5 s. 1000 + 1000 particles, two seeds, the experiment's own
// settings.
class TwinMugs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    config_ = sim::load_experiment(std::string(OPF_SOURCE_DIR) + "/experiments/twin_mugs.yaml");
    observation_ = observe_experiment(config_);
  }
  static ExperimentResults run(const EstimatorSettings& settings) {
    return run_open_loop(config_, observation_, {"opf"}, settings, 3, 5);
  }
  static EstimatorSettings settings() {
    EstimatorSettings s =
        (config_.estimator_config.empty() ? EstimatorSettings{}
                                          : load_estimator_settings(config_.estimator_config));
    s.pf.translation_particles = s.pf.rotation_particles = 1000;
    s.opf.occluder.camera_position = config_.camera.position;  // as `opf run` passes it
    return s;
  }
  static inline sim::ExperimentConfig config_;
  static inline Observation observation_;
};

TEST_F(TwinMugs, OneHypothesisFollowsEachMugAndTheRightOneSurvivesTheReveal) {
  const ExperimentResults r = run(settings());
  const HypothesisStats h = hypothesis_stats(r, "opf");
  // The tie fires at onset (the mugs' distances differ by the estimates' few mm, under the
  // 1 cm epsilon_occ) and both hypotheses live through every hidden frame of every seed.
  ASSERT_GT(h.hidden_frames, 150u);
  EXPECT_EQ(h.with_more, h.hidden_frames);
  // The hypothesis following mug B is held while B closes in and slides over the ball, then
  // carried at its offset of B's closest approach: the estimates' few mm (4-9 mm in each of ten
  // seeds, with 1000 or 5000 particles). The bound for the tie: 15 mm.
  EXPECT_LT(h.nearest_hidden_translation, 0.015);
  // Seen again under mug B's last place: one hypothesis is left, on the ball.
  for (const FrameRecord& record : r.records) {
    if (record.frame < config_.frames - 30) continue;
    EXPECT_EQ(record.estimate.hypothesis, 0) << record.frame;
    if (record.estimate.object != "ball") continue;
    EXPECT_LT((translation_of(record.estimate.pose.mean) - record.truth.position).norm(), 0.01)
        << record.frame;
  }
  // Mid-carry (4 s) one hypothesis is on the ball and the other with mug A, which is 0.39 m
  // away by then: they are over 0.3 m apart.
  std::map<std::size_t, std::vector<const FrameRecord*>> at_four_seconds;
  for (const FrameRecord& record : r.records)
    if (record.frame == 120 && record.estimate.object == "ball")
      at_four_seconds[record.seed_index].push_back(&record);
  ASSERT_EQ(at_four_seconds.size(), 3u);
  for (const auto& [seed, both] : at_four_seconds) {
    ASSERT_EQ(both.size(), 2u) << seed;
    const auto error = [](const FrameRecord* record) {
      return (translation_of(record->estimate.pose.mean) - record->truth.position).norm();
    };
    EXPECT_LT(std::min(error(both[0]), error(both[1])), 0.05) << seed;
    EXPECT_GT(
        (translation_of(both[0]->estimate.pose.mean) - translation_of(both[1]->estimate.pose.mean))
            .norm(),
        0.3)
        << seed;
  }
}

TEST_F(TwinMugs, CarriedFromOnsetTheBallsMugIsFollowedAtItsCentre) {
  // Without waiting for the departure, the hypothesis following mug B takes B's centre from
  // onset, 4.5-5.5 cm beside the ball until B has slid over it at 3 s: over a third of the 93
  // hidden frames, about 15 mm on average on top of the carry's few mm (18 mm here).
  EstimatorSettings s = settings();
  s.opf.occluder.carry_from_departure = false;
  EXPECT_GT(hypothesis_stats(run(s), "opf").nearest_hidden_translation, 0.015);
}

}  // namespace
}  // namespace opf::experiments
