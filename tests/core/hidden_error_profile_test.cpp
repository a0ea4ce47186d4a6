#include "opf/core/hidden_error_profile.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace opf {
namespace {

TEST(HiddenErrorProfile, ThirtyHertzFramesFallInTenthsOfASecond) {
  HiddenErrorProfile profile;
  // Frames 1-3 after the last measurement are in (0, 0.1] s, frame 4 in (0.1, 0.2].
  for (int k = 1; k <= 4; ++k) profile.add(k / 30.0, 0.01 * k, 0.1 * k);
  const auto bins = profile.means();
  ASSERT_EQ(bins.size(), 2u);
  EXPECT_EQ(bins[0].frames, 3u);
  EXPECT_NEAR(bins[0].translation, 0.02, 1e-15);
  EXPECT_NEAR(bins[0].rotation, 0.2, 1e-15);
  EXPECT_EQ(bins[1].frames, 1u);
  EXPECT_NEAR(bins[1].translation, 0.04, 1e-15);
}

TEST(HiddenErrorProfile, EmptyBinsStayEmpty) {
  HiddenErrorProfile profile;
  profile.add(0.35, 1.0, 2.0);
  const auto bins = profile.means();
  ASSERT_EQ(bins.size(), 4u);
  EXPECT_EQ(bins[0].frames + bins[1].frames + bins[2].frames, 0u);
  EXPECT_EQ(bins[3].frames, 1u);
}

TEST(HiddenErrorProfile, RefusesATimeThatIsNotAfterTheLastMeasurement) {
  HiddenErrorProfile profile;
  EXPECT_THROW(profile.add(0.0, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(profile.add(-1.0, 1.0, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace opf
