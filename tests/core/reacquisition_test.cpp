#include "opf/core/reacquisition.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opf {
namespace {

TEST(Reacquisition, FirstErrorAndFramesUntilWithinTwiceTheVisibleError) {
  Reacquisition r;
  // Visible errors 0.01 (x6) and the reacquisition frames 0.05, 0.03, 0.01 (visible too):
  // visible mean (6 x 0.01 + 0.05 + 0.03 + 0.01) / 9 = 0.0167, settled at 0.0333 or below.
  for (int k = 0; k < 3; ++k) r.add("a", true, 0.01);
  r.add("a", false, 0.2);
  r.add("a", false, 0.3);
  r.add("a", true, 0.05);
  r.add("a", true, 0.03);
  r.add("a", true, 0.01);
  for (int k = 0; k < 3; ++k) r.add("a", true, 0.01);
  const ReacquisitionResult result = r.result();
  EXPECT_EQ(result.gaps, 1u);
  EXPECT_NEAR(result.first_error, 0.05, 1e-15);
  EXPECT_NEAR(result.frames_to_settle, 1.0, 1e-15);  // 0.03 is within 2 x 0.0167
}

TEST(Reacquisition, GapsOfSeveralObjectsAreAveraged) {
  Reacquisition r;
  r.add("a", true, 0.01);
  r.add("b", true, 0.01);
  r.add("a", false, 0.5);
  r.add("b", false, 0.5);
  r.add("a", true, 0.01);  // settled at once
  r.add("b", true, 0.09);  // never settles: counts its 2 frames
  r.add("b", true, 0.09);
  const ReacquisitionResult result = r.result(1.0);
  EXPECT_EQ(result.gaps, 2u);
  EXPECT_NEAR(result.first_error, 0.05, 1e-15);
  EXPECT_NEAR(result.frames_to_settle, 1.0, 1e-15);
}

TEST(Reacquisition, NoGapGivesNaN) {
  Reacquisition r;
  r.add("a", true, 0.01);
  r.add("a", false, 0.01);  // hidden to the end: no reacquisition
  const ReacquisitionResult result = r.result();
  EXPECT_EQ(result.gaps, 0u);
  EXPECT_TRUE(std::isnan(result.first_error));
  EXPECT_TRUE(std::isnan(result.frames_to_settle));
}

}  // namespace
}  // namespace opf
