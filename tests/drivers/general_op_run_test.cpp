#include "drivers/experiment_run.h"

#include "bundled_experiment.h"
#include "drivers/observe_experiment.h"

#include <gtest/gtest.h>

namespace opf::experiments {
namespace {

// general_op (Table I), rendered, 1000 + 1000 particles, three seeds, the default settings: the
// ball is carried under a mug, then rolls under a tray. The OPF's mean translation error is
// 0.0057 m here and 0.0113 m while hidden (the paper's OPF: 0.0114 m over all frames). Bounded
// 15% above those: two steps at the ball's reappearance from under the mug are what keep it
// there, and neither had a test: the history restarts (it was carried, not moving on its own:
// 0.0073 m without), and so do the motion-model banks (0.0082 m without).
TEST(GeneralOp, TheOpfKeepsTheBallWithinItsTableIError) {
  const sim::ExperimentConfig config = bundled_experiment("general_op");
  const Observation observation = observe_experiment(config);
  const EstimatorSettings settings = default_settings(config, 1000);
  const ExperimentResults r = run_open_loop(config, observation, {"opf"}, settings, 3, 7);
  double translation = 0.0, hidden = 0.0;
  for (const RunErrors& e : r.runs.at("opf")) {
    translation += e.translation / 3.0;
    hidden += e.translation_unobserved / 3.0;
  }
  EXPECT_LT(translation, 0.0065);
  EXPECT_LT(hidden, 0.013);
}

}  // namespace
}  // namespace opf::experiments
