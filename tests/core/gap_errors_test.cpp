#include "opf/core/gap_errors.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

TEST(GapErrors, EachStretchWithoutADetectionIsAGapOfItsObject) {
  GapErrors gaps;
  // The cup detected at 0, missing at 1 and 2, detected at 3, missing at 4 (still open); the ball
  // missing at 2, inside the cup's first gap.
  gaps.add("cup", 0.0, true, 0.001, 0.01);
  gaps.add("cup", 1.0, false, 0.010, 0.10);
  gaps.add("cup", 2.0, false, 0.030, 0.20);
  gaps.add("ball", 2.0, false, 0.500, 0.50);
  gaps.add("cup", 3.0, true, 0.002, 0.02);
  gaps.add("cup", 4.0, false, 0.040, 0.40);
  const auto& all = gaps.gaps();
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].object, "cup");
  EXPECT_EQ(all[0].start, 1.0);
  EXPECT_EQ(all[0].end, 2.0);
  EXPECT_EQ(all[0].frames, 2u);
  EXPECT_DOUBLE_EQ(all[0].translation, 0.040);  // sums; a detected frame adds nothing
  EXPECT_DOUBLE_EQ(all[0].rotation, 0.30);
  EXPECT_EQ(all[1].object, "ball");
  EXPECT_EQ(all[1].frames, 1u);
  EXPECT_EQ(all[2].object, "cup");
  EXPECT_EQ(all[2].start, 4.0);
  EXPECT_EQ(all[2].end, 4.0);
  EXPECT_DOUBLE_EQ(all[2].translation, 0.040);
}

}  // namespace
}  // namespace opf
