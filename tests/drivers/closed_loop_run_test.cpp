#include "drivers/closed_loop_run.h"

#include "bundled_experiment.h"
#include "opf/core/pose_conversion.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace opf::experiments {
namespace {

// The paper's experiment 2 in closed loop, shortened to its first 3 s (the mug from y = 0.45 to
// 0), 1000 + 1000 particles, one seed of the OPF.
class SugarDropStart : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    sim::ExperimentConfig config = bundled_experiment("sugar_drop");
    config.frames = 90;
    EstimatorSettings settings;  // the defaults, as `opf run` runs every experiment
    settings.pf.translation_particles = settings.pf.rotation_particles = 1000;
    results_ = new ExperimentResults(run_closed_loop(config, {"opf"}, settings, 1, 3));
  }
  static void TearDownTestSuite() { delete results_; }

  static std::vector<const FrameRecord*> of(const std::string& object) {
    std::vector<const FrameRecord*> records;
    for (const FrameRecord& r : results_->records)
      if (r.estimate.object == object && r.estimate.hypothesis == 0) records.push_back(&r);
    return records;
  }
  static ExperimentResults* results_;
};
ExperimentResults* SugarDropStart::results_ = nullptr;

// What a closed loop's camera sees depends on the robot, so the check follows the run: with the
// camera under the table no run estimates the mug, and none is scored as if it had.
TEST(ClosedLoopRun, RefusesAnObjectOfInterestNoRunEstimates) {
  sim::ExperimentConfig config = bundled_experiment("sugar_drop");
  config.frames = 5;
  config.camera.position.z() = -5.0;
  EstimatorSettings settings;
  settings.pf.translation_particles = settings.pf.rotation_particles = 100;
  try {
    run_closed_loop(config, {"pf"}, settings, 1, 3);
    FAIL() << "a closed loop that never measured the mug was scored";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the object of interest 'mug' in none of its 5 frames"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(SugarDropStart, TheHandWaitsThenTracksTheMugAndHidesItItself) {
  const auto hand = of("hand");
  const auto mug = of("mug");
  ASSERT_EQ(hand.size(), 90u);
  ASSERT_EQ(mug.size(), 90u);
  // Until the mug passes y = 0.25 (t = 1.33 s, frame 40) the hand stays where it waits.
  EXPECT_LT((hand[30]->truth.position - Eigen::Vector3d(0.35, 0.25, 0.25)).norm(), 1e-12);
  // One second later (k_p = 3 /s: three time constants) it hovers over the mug, within the
  // mug's radius, 0.2 m above it.
  const Eigen::Vector3d offset = hand[89]->truth.position - mug[89]->truth.position;
  EXPECT_LT(offset.head<2>().norm(), 0.045);
  EXPECT_NEAR(offset.z(), 0.2, 0.02);
  // Over the mug, the hand hides it from the camera: the mug goes unmeasured.
  int hidden = 0;
  for (int k = 60; k < 90; ++k) hidden += !mug[k]->visible;
  EXPECT_GT(hidden, 20);
  // And the OPF carried it through along the motion-model bank's prediction: within 3 cm at the
  // end (2 cm here: the mug's partly covered last glimpses slow the bank's velocity; Table I's
  // sugar_drop error shows the same, docs/dynamics.md).
  EXPECT_LT((translation_of(mug[89]->estimate.pose.mean) - mug[89]->truth.position).norm(), 0.03);
}

TEST_F(SugarDropStart, TheSameSeedGivesTheSameRun) {
  sim::ExperimentConfig config = bundled_experiment("sugar_drop");
  config.frames = 90;
  EstimatorSettings settings;
  settings.pf.translation_particles = settings.pf.rotation_particles = 1000;
  const ExperimentResults again = run_closed_loop(config, {"opf"}, settings, 1, 3);
  ASSERT_EQ(again.records.size(), results_->records.size());
  EXPECT_EQ(again.records.back().truth.position, results_->records.back().truth.position);
  EXPECT_EQ(again.runs.at("opf")[0].translation, results_->runs.at("opf")[0].translation);
}

}  // namespace
}  // namespace opf::experiments
