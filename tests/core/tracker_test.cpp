#include "opf/core/tracker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>

namespace opf {
namespace {

// A recording estimator: echoes its measurement (or holds the last one) and records what the
// tracker showed it, so the tracker's bookkeeping can be checked exactly.
class RecordingEstimator final : public Estimator {
 public:
  struct Log {
    std::vector<std::size_t> ensemble_sizes;
    std::vector<double> hand_radii;  ///< the hand's size as the view stated it, each step
    std::vector<double> hand_box_x;  ///< the first extent of the hand's stated box, each step
    std::uint64_t seed = 0;
  };
  RecordingEstimator(std::uint64_t seed, Log& log) : log_(log) { log_.seed = seed; }
  std::string_view name() const override { return "recording"; }
  Estimate initialise(double t, const mrpt::poses::CPose3D& z) override {
    last_ = z;
    return make(t, EstimateMode::kMeasured);
  }
  Estimate step(double t, const mrpt::poses::CPose3D* z, const EnsembleView& view) override {
    log_.ensemble_sizes.push_back(view.previous_estimates.size());
    log_.hand_radii.push_back(stated_radius(view, "hand"));
    log_.hand_box_x.push_back(stated_box(view, "hand").x());
    if (z) last_ = *z;
    return make(t, z ? EstimateMode::kMeasured : EstimateMode::kPredicted);
  }

 private:
  Estimate make(double t, EstimateMode mode) const {
    Estimate e;
    e.t = t;
    e.pose = mrpt::poses::CPose3DPDFGaussian(last_);
    e.mode = mode;
    return e;
  }
  Log& log_;
  mrpt::poses::CPose3D last_;
};

Frame frame(double t, std::vector<std::pair<std::string, double>> detections) {
  Frame f{t, {}};
  for (auto& [name, x] : detections)
    f.detections.push_back({name, mrpt::poses::CPose3D(x, 0, 0, 0, 0, 0)});
  return f;
}

// A factory of recording estimators, each logging into its object's entry of `logs`.
EstimatorFactory recording_into(std::map<std::string, RecordingEstimator::Log>& logs) {
  return [&logs](const std::string& object, std::uint64_t seed) {
    return std::make_unique<RecordingEstimator>(seed, logs[object]);
  };
}

// Holds a second hypothesis beside its estimate, as the OPF's occluder module does: `left` at
// the first position it was shown, with probability 0.25.
class TwoHypothesesEstimator final : public Estimator {
 public:
  std::string_view name() const override { return "two hypotheses"; }
  Estimate initialise(double t, const mrpt::poses::CPose3D& z) override {
    first_ = last_ = z;
    t_ = t;
    return at(t, last_);
  }
  Estimate step(double t, const mrpt::poses::CPose3D* z, const EnsembleView&) override {
    if (z) last_ = *z;
    t_ = t;
    return at(t, last_);
  }
  std::vector<Estimate> extra_hypotheses() const override {
    Estimate left = at(t_, first_);
    left.mode = EstimateMode::kLeft;
    left.hypothesis = 1;
    left.probability = 0.25;
    return {left};
  }

 private:
  Estimate at(double t, const mrpt::poses::CPose3D& pose) const {
    Estimate e;
    e.t = t;
    e.pose = mrpt::poses::CPose3DPDFGaussian(pose);
    e.probability = 0.75;
    return e;
  }
  double t_ = 0.0;
  mrpt::poses::CPose3D first_, last_;
};

TEST(Tracker, CreatesEstimatorsAtFirstDetectionInOrderOfAppearance) {
  std::map<std::string, RecordingEstimator::Log> logs;
  Tracker tracker(recording_into(logs), 99);
  EXPECT_EQ(tracker.step(frame(0.0, {{"mug", 1.0}})).size(), 1u);
  const auto& second = tracker.step(frame(0.1, {{"ball", 2.0}}));
  ASSERT_EQ(second.size(), 2u);
  EXPECT_EQ(second[0].object, "mug");
  EXPECT_EQ(second[0].mode, EstimateMode::kPredicted);
  EXPECT_DOUBLE_EQ(second[0].pose.mean.x(), 1.0);
  EXPECT_EQ(second[1].object, "ball");
  EXPECT_EQ(second[1].mode, EstimateMode::kMeasured);
  const auto& third = tracker.step(frame(0.2, {{"ball", 3.0}, {"mug", 4.0}}));
  EXPECT_DOUBLE_EQ(third[0].pose.mean.x(), 4.0);
  EXPECT_DOUBLE_EQ(third[1].pose.mean.x(), 3.0);
  EXPECT_DOUBLE_EQ(third[1].t, 0.2);
  // Each estimator saw the previous frame's estimates of the whole ensemble.
  EXPECT_EQ(logs["mug"].ensemble_sizes, (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(logs["ball"].ensemble_sizes, (std::vector<std::size_t>{2}));
  // Seeds differ per object and are reproducible.
  EXPECT_NE(logs["mug"].seed, logs["ball"].seed);
}

// The sizes the detections state are remembered for every estimator to read: a hand hidden now
// keeps the size it last stated, a new statement replaces it, and an object that never stated
// one has none.
TEST(Tracker, KeepsEachObjectsLastStatedSize) {
  std::map<std::string, RecordingEstimator::Log> logs;
  Tracker tracker(recording_into(logs), 99);
  const auto with_hand = [](double t, double radius, double box = 0.0) {
    Frame f = frame(t, {{"cube", 0.0}, {"hand", 0.1}});
    f.detections[1].radius = radius;
    f.detections[1].box = Eigen::Vector3d::Constant(box);
    return f;
  };
  tracker.step(frame(0.0, {{"cube", 0.0}}));
  tracker.step(with_hand(0.1, 0.0));
  tracker.step(with_hand(0.2, 0.07));
  tracker.step(frame(0.3, {{"cube", 0.0}}));
  tracker.step(with_hand(0.4, 0.05, 0.14));
  tracker.step(with_hand(0.5, 0.0));  // states neither: both kept
  tracker.step(with_hand(0.6, 0.06));
  EXPECT_EQ(logs["cube"].hand_radii, (std::vector<double>{0.0, 0.07, 0.07, 0.05, 0.05, 0.06}));
  EXPECT_EQ(logs["cube"].hand_box_x, (std::vector<double>{0.0, 0.0, 0.0, 0.14, 0.14, 0.14}));
}

TEST(Tracker, RejectsFramesThatDoNotAdvanceInTime) {
  std::map<std::string, RecordingEstimator::Log> logs;
  Tracker tracker(recording_into(logs), 1);
  tracker.step(frame(1.0, {{"a", 0.0}}));
  EXPECT_THROW(tracker.step(frame(1.0, {{"a", 0.0}})), std::invalid_argument);
  EXPECT_THROW(tracker.step(frame(0.5, {{"a", 0.0}})), std::invalid_argument);
}

TEST(Tracker, RefusesANonFiniteTimeAndKeepsGoing) {
  std::map<std::string, RecordingEstimator::Log> logs;
  Tracker tracker(recording_into(logs), 1);
  // Also as the first frame: taken, it would leave no later time accepted.
  EXPECT_THROW(tracker.step(frame(std::nan(""), {{"a", 0.0}})), std::invalid_argument);
  EXPECT_TRUE(tracker.estimates().empty());
  EXPECT_EQ(tracker.step(frame(1.0, {{"a", 0.0}})).size(), 1u);
  EXPECT_THROW(tracker.step(frame(HUGE_VAL, {{"a", 0.0}})), std::invalid_argument);
  EXPECT_EQ(tracker.step(frame(2.0, {{"a", 0.0}})).size(), 1u);
}

// An estimate that is not a number is an error, not a row: written, a NaN would pass for an
// estimate. Here the recording estimator echoes a detection at NaN.
TEST(Tracker, RefusesAnEstimateThatIsNotFinite) {
  std::map<std::string, RecordingEstimator::Log> logs;
  Tracker tracker(recording_into(logs), 1);
  tracker.step(frame(1.0, {{"a", 0.5}}));
  try {
    tracker.step(frame(2.0, {{"a", std::nan("")}}));
    FAIL() << "a NaN pose was taken";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("recording: the estimate of 'a' at t = 2 s"), std::string::npos)
        << message;
    EXPECT_NE(message.find("has a pose that is not a finite number"), std::string::npos) << message;
  }
  // The estimator has stepped into that state: the tracker goes no further.
  try {
    tracker.step(frame(3.0, {{"a", 0.5}}));
    FAIL() << "a tracker stepped on after a refused estimate";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("stopped at a refused estimate (t = 2 s)"),
              std::string::npos)
        << e.what();
  }
}

TEST(Tracker, RefusesEachNonFiniteFieldByName) {
  const auto message_for = [](const std::function<void(Estimate&)>& spoil) {
    Estimate e;
    e.object = "cup";
    e.t = 0.5;
    e.hypothesis = 2;
    EXPECT_NO_THROW(refuse_non_finite(e, "opf"));
    spoil(e);
    try {
      refuse_non_finite(e, "opf");
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  const std::string covariance = message_for([](Estimate& e) { e.pose.cov(3, 4) = HUGE_VAL; });
  EXPECT_NE(covariance.find("'cup' at t = 0.5 s (hypothesis 2) has a covariance"),
            std::string::npos)
      << covariance;
  EXPECT_NE(message_for([](Estimate& e) { e.observation_trace = std::nan(""); }).find("trace(Q)"),
            std::string::npos);
  EXPECT_NE(message_for([](Estimate& e) { e.probability = std::nan(""); }).find("probability"),
            std::string::npos);
  EXPECT_NE(message_for([](Estimate& e) { e.pose.mean.z(-HUGE_VAL); }).find("a pose"),
            std::string::npos);
}

// A frame's rows as an estimate file lists them: every object's main estimate in order of first
// appearance, then the further hypotheses in the same order, all marked in a frame filled inside
// a gap; the vector is refilled, not appended to.
TEST(Tracker, StepIntoRowsListsMainEstimatesThenFurtherHypotheses) {
  Tracker tracker(
      [](const std::string&, std::uint64_t) { return std::make_unique<TwoHypothesesEstimator>(); },
      7);
  std::vector<Estimate> rows(3);
  step_into_rows(tracker, frame(0.0, {{"mug", 1.0}, {"ball", 2.0}}), rows);
  Frame filled = frame(0.1, {{"ball", 3.0}});
  filled.filled = true;
  for (const bool is_filled : {false, true}) {
    if (is_filled) step_into_rows(tracker, filled, rows);
    ASSERT_EQ(rows.size(), 4u);
    const std::vector<std::pair<std::string, int>> order = {
        {"mug", 0}, {"ball", 0}, {"mug", 1}, {"ball", 1}};
    for (std::size_t i = 0; i < rows.size(); ++i) {
      EXPECT_EQ(rows[i].object, order[i].first) << i;
      EXPECT_EQ(rows[i].hypothesis, order[i].second) << i;
      EXPECT_DOUBLE_EQ(rows[i].probability, order[i].second == 0 ? 0.75 : 0.25) << i;
      EXPECT_EQ(rows[i].recovery.frame_filled, is_filled) << i;
      EXPECT_DOUBLE_EQ(rows[i].t, is_filled ? 0.1 : 0.0) << i;
    }
  }
  EXPECT_DOUBLE_EQ(rows[1].pose.mean.x(), 3.0);  // the ball's main estimate, at its detection
  EXPECT_DOUBLE_EQ(rows[3].pose.mean.x(), 2.0);  // its hypothesis, where it was first seen
}

}  // namespace
}  // namespace opf
