#include "opf/core/recovery_events.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

TEST(RecoveryEvents, ModeColumnIsTheModeWordThenEachEventInOrder) {
  EXPECT_EQ(mode_column(EstimateMode::kMeasured, {}), "measured");
  EXPECT_EQ(mode_column(EstimateMode::kMeasured, {.sensor_reset = true}), "measured+reset");
  EXPECT_EQ(mode_column(EstimateMode::kCarried, {.weights_underflow = true, .trace_capped = true}),
            "carried+underflow+capped");
  EXPECT_EQ(mode_column(EstimateMode::kRandomWalk,
                        {.sensor_reset = true, .weights_underflow = true, .trace_capped = true}),
            "random_walk+reset+underflow+capped");
  EXPECT_FALSE(RecoveryEvents{}.any());
  EXPECT_TRUE(RecoveryEvents{.trace_capped = true}.any());
}

TEST(RecoveryEvents, EveryWrittenColumnParsesBackToWhatWasWritten) {
  for (const auto& entry : kEstimateModeNames) {
    const EstimateMode mode = entry.value;
    for (int bits = 0; bits < 8; ++bits) {
      const RecoveryEvents events{.sensor_reset = (bits & 1) != 0,
                                  .weights_underflow = (bits & 2) != 0,
                                  .trace_capped = (bits & 4) != 0};
      const std::string text = mode_column(mode, events);
      const auto parsed = parse_mode_column(text);
      ASSERT_TRUE(parsed) << text;
      EXPECT_EQ(parsed->mode, mode) << text;
      EXPECT_EQ(parsed->events, events) << text;
    }
  }
}

TEST(RecoveryEvents, TheOlderWordOccluderReadsAsCarried) {
  const auto parsed = parse_mode_column("occluder+capped");
  ASSERT_TRUE(parsed);
  EXPECT_EQ(parsed->mode, EstimateMode::kCarried);
  EXPECT_TRUE(parsed->events.trace_capped);
}

TEST(RecoveryEvents, RejectsUnknownWordsAndOtherSpellings) {
  for (const char* text :
       {"", "measure", "Measured", "measured+", "+reset", "measured+bogus", "measured++reset",
        "measured+capped+reset", "measured+reset+reset", "measured reset", "measured+reset "})
    EXPECT_FALSE(parse_mode_column(text)) << "'" << text << "'";
}

}  // namespace
}  // namespace opf
