#include "opf/core/pose_conversion.h"
#include "opf/core/tracker.h"
#include "opf/estimators/object_permanence_filter.h"
#include "opf/io/measurement_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace opf {
namespace {

// The cup clip's detections (data/README.md) with those from 7.02 to 7.58 s taken away (the
// real-motion benchmark's 0.6 s dropout there): the OPF's mean error over those frames against
// the detections taken away. `mend`: the depth of the frame at 6.24 s, 7 cm below the frame before
// and 5 cm off its neighbours' mean (the cup's size misread in that frame alone), replaced by
// that mean.
double hidden_error(bool mend, std::uint64_t seed) {
  MeasurementLog log = read_measurement_log(std::string(OPF_SOURCE_DIR) +
                                            "/tests/estimators/data/cup_clip_detections.csv");
  std::vector<Frame>& frames = log.frames;
  int misread = 0;
  for (std::size_t k = 1; k + 1 < frames.size(); ++k) {
    if (std::abs(frames[k].t - 6.2367) > 1e-3) continue;
    Eigen::Vector3d p = translation_of(frames[k].detections.at(0).pose);
    const double between = 0.5 * (translation_of(frames[k - 1].detections.at(0).pose).z() +
                                  translation_of(frames[k + 1].detections.at(0).pose).z());
    EXPECT_GT(std::abs(p.z() - between), 0.045);
    ++misread;
    if (!mend) continue;
    p.z() = between;
    frames[k].detections[0].pose = make_pose(p, orientation_of(frames[k].detections[0].pose));
  }
  EXPECT_EQ(misread, 1);
  Tracker tracker(
      [](const std::string& object, std::uint64_t s) {
        return std::make_unique<ObjectPermanenceFilter>(OpfOptions{}, object, s);
      },
      seed);
  double sum = 0.0;
  int hidden = 0;
  for (Frame frame : frames) {
    const bool gap = frame.t >= 7.02 && frame.t < 7.59;
    const Eigen::Vector3d seen = translation_of(frame.detections.at(0).pose);
    if (gap) frame.detections.clear();
    const Estimate& e = tracker.step(frame).at(0);
    if (!gap) continue;
    sum += (translation_of(e.pose.mean) - seen).norm();
    ++hidden;
  }
  EXPECT_EQ(hidden, 16);
  return sum / hidden;
}

// That one misread depth lies outside the banks' validation gate: it is held back, and dropped
// when the next detection is inside, so it never sets the velocity the hidden cup follows 0.8 s
// later. The cup then comes through the gap as it does with the depth mended, to within the
// particles' own noise (the particle filter itself still takes the detection); taken at face
// value, the misread depth would turn the banks' velocity and double the error over the gap (45
// against 21 mm). Within 5 mm: the two logs' runs differ by up to 2 mm in these seeds.
TEST(ObjectPermanenceFilter, OneMisreadDepthDoesNotSteerTheCupThroughTheNextGap) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed)
    EXPECT_NEAR(hidden_error(false, seed), hidden_error(true, seed), 0.005) << "seed " << seed;
}

}  // namespace
}  // namespace opf
