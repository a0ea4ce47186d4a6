#include "opf/io/unsized_log_note.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

Estimate in_mode(EstimateMode mode) {
  Estimate estimate;
  estimate.mode = mode;
  return estimate;
}

Detection stating(double radius, const Eigen::Vector3d& box) {
  Detection detection;
  detection.object = "mug";
  detection.radius = radius;
  detection.box = box;
  return detection;
}

TEST(UnsizedLogWatch, IsDueOnceTheOccluderModuleTookAnObjectAndNoSizeWasStated) {
  for (const EstimateMode took : {EstimateMode::kCarried, EstimateMode::kLeft}) {
    UnsizedLogWatch watch;
    watch.saw(stating(0.0, Eigen::Vector3d::Zero()));
    for (const EstimateMode other : {EstimateMode::kMeasured, EstimateMode::kPredicted,
                                     EstimateMode::kDynamics, EstimateMode::kRandomWalk})
      watch.saw(in_mode(other));
    EXPECT_FALSE(watch.note_due());
    watch.saw(in_mode(took));
    EXPECT_TRUE(watch.note_due());
    watch.saw(in_mode(EstimateMode::kMeasured));  // what was taken stays taken
    EXPECT_TRUE(watch.note_due());
  }
}

TEST(UnsizedLogWatch, IsNotDueWhereAnyDetectionStatesARadiusOrABox) {
  for (const Detection& sized :
       {stating(0.05, Eigen::Vector3d::Zero()), stating(0.0, Eigen::Vector3d(0.0, 0.0, 0.02))}) {
    UnsizedLogWatch watch;
    watch.saw(in_mode(EstimateMode::kCarried));
    watch.saw(sized);  // one stated size anywhere in the log, before or after
    watch.saw(stating(0.0, Eigen::Vector3d::Zero()));
    EXPECT_FALSE(watch.note_due());
  }
}

TEST(UnsizedLogWatch, TheNoteNamesTheColumnsThatStateSizes) {
  const std::string note = unsized_log_note();
  EXPECT_NE(note.find("the radius or box_x,box_y,box_z columns"), std::string::npos) << note;
  EXPECT_EQ(note.find('\n'), std::string::npos) << note;
}

}  // namespace
}  // namespace opf
