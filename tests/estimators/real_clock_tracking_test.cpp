// Tracking logs shaped like real systems write them, end to end through the log reader and the
// OPF with default settings: per-object clocks a fraction of a millisecond apart track as well as
// aligned ones, and a thrown ball is estimated in every frame of a 0.5 s gap with no rows.

#include "opf/core/random.h"
#include "opf/core/tracker.h"
#include "opf/estimators/registry.h"
#include "opf/io/measurement_log.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace opf {
namespace {

using Trajectory = std::function<Eigen::Vector3d(double t)>;

std::string row(double t, const std::string& object, const Eigen::Vector3d& p) {
  std::ostringstream s;
  s.precision(17);
  s << t << ',' << object << ',' << p.x() << ',' << p.y() << ',' << p.z() << ",0,0,0,1\n";
  return s.str();
}

struct TrackedObject {
  std::string name;
  Trajectory truth;
  double clock_offset = 0.0;                  // s, this object's sensor clock
  std::function<bool(double t)> hidden = {};  // no row while true
};

// A 30 Hz log of `objects` with 2 mm noise (seeded); each object stamped by its own clock.
std::string make_log(const std::vector<TrackedObject>& objects, int frames, std::uint64_t seed) {
  Random noise(seed);
  std::string text = "t,object,x,y,z,qx,qy,qz,qw\n";
  for (int k = 0; k < frames; ++k)
    for (const TrackedObject& o : objects) {
      const double t = k / 30.0;
      const Eigen::Vector3d n(noise.normal(), noise.normal(), noise.normal());
      if (o.hidden && o.hidden(t)) continue;
      text += row(t + o.clock_offset, o.name, o.truth(t) + 0.002 * n);
    }
  return text;
}

/// Mean translation error of `object` over its hidden frames, and the frames and estimates seen.
struct HiddenError {
  double mean = 0.0;
  std::size_t hidden_frames = 0;
  std::size_t frames = 0;
  std::size_t estimates = 0;
};

HiddenError hidden_error(const std::string& log_text, const TrackedObject& object) {
  std::istringstream in(log_text);
  const MeasurementLog log = parse_measurement_log(in, "log.csv");
  Tracker tracker(make_estimator_factory("opf", EstimatorSettings{}), 3, 1);
  HiddenError result;
  for (const Frame& frame : log.frames) {
    ++result.frames;
    for (const Estimate& e : tracker.step(frame)) {
      ++result.estimates;
      if (e.object != object.name || frame.find(object.name)) continue;
      const Eigen::Vector3d p(e.pose.mean.x(), e.pose.mean.y(), e.pose.mean.z());
      result.mean += (p - object.truth(frame.t)).norm();
      ++result.hidden_frames;
    }
  }
  if (result.hidden_frames > 0) result.mean /= static_cast<double>(result.hidden_frames);
  return result;
}

TEST(RealClockTracking, PerObjectClocksTrackAsWellAsAlignedOnes) {
  const auto ball = [](double t) { return Eigen::Vector3d(0.2 + 0.3 * t, 0.1, 0.5); };
  const auto mug = [](double) { return Eigen::Vector3d(0.6, 0.1, 0.45); };
  const auto box = [](double t) {
    return Eigen::Vector3d(0.3 * std::cos(0.8 * t), -0.3 + 0.3 * std::sin(0.8 * t), 0.4);
  };
  const auto hidden = [](double t) { return std::fmod(t, 1.0) >= 0.5 && std::fmod(t, 1.0) < 0.8; };
  constexpr int kFrames = 90;
  std::vector<TrackedObject> aligned = {{"ball", ball, 0.0, hidden}, {"mug", mug}, {"box", box}};
  std::vector<TrackedObject> jittered = aligned;
  jittered[1].clock_offset = 0.0003;  // clocks up to 0.5 ms apart
  jittered[2].clock_offset = 0.0005;

  const HiddenError reference = hidden_error(make_log(aligned, kFrames, 11), aligned[0]);
  const HiddenError result = hidden_error(make_log(jittered, kFrames, 11), jittered[0]);
  // One estimate per object per real frame.
  EXPECT_EQ(result.frames, static_cast<std::size_t>(kFrames));
  EXPECT_EQ(result.estimates, 3u * kFrames);
  EXPECT_EQ(result.hidden_frames, reference.hidden_frames);
  EXPECT_GE(result.hidden_frames, 27u);  // 0.3 s of each second, 3 seconds
  // The 0.5 ms clock offset moves the ball by 0.15 mm: no more than noise apart.
  EXPECT_LE(result.mean, 1.3 * reference.mean + 0.001)
      << "aligned " << reference.mean << " m, jittered " << result.mean << " m";
  EXPECT_LT(reference.mean, 0.02);
}

TEST(RealClockTracking, AThrownBallIsEstimatedInEveryFrameOfAGapWithNoRows) {
  // 100 Hz motion capture of a ball in flight; no rows at all for 0.5 s.
  const auto ball = [](double t) {
    return Eigen::Vector3d(0.5 + 2.0 * t, 0.2 - 0.5 * t, 1.0 + 6.0 * t - 0.5 * 9.81 * t * t);
  };
  Random noise(5);
  std::string text = "t,object,x,y,z,qx,qy,qz,qw\n";
  for (int k = 0; k < 120; ++k) {
    const double t = k / 100.0;
    const Eigen::Vector3d n(noise.normal(), noise.normal(), noise.normal());
    if (t >= 0.5 && t < 1.0 - 1e-9) continue;
    text += row(t, "ball", ball(t) + 0.001 * n);
  }
  std::istringstream in(text);
  const MeasurementLog log = parse_measurement_log(in, "mocap.csv");
  ASSERT_EQ(log.frames.size(), 120u);
  EXPECT_EQ(log.report.filled_frames, 50u);
  Tracker tracker(make_estimator_factory("opf", EstimatorSettings{}), 1, 1);
  std::size_t estimated = 0;
  double worst = 0.0;
  for (const Frame& frame : log.frames) {
    const auto& estimates = tracker.step(frame);
    ASSERT_EQ(estimates.size(), 1u);
    if (!frame.filled) continue;
    const auto& mean = estimates[0].pose.mean;
    worst = std::max(worst, (Eigen::Vector3d(mean.x(), mean.y(), mean.z()) - ball(frame.t)).norm());
    ++estimated;
  }
  EXPECT_EQ(estimated, 50u);
  EXPECT_LT(worst, 0.02);
}

}  // namespace
}  // namespace opf
