#include "opf/core/closest_name.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

TEST(ClosestName, EditDistanceCountsTheUsualTypos) {
  EXPECT_EQ(edit_distance("track", "track"), 0u);
  EXPECT_EQ(edit_distance("trak", "track"), 1u);   // a deletion
  EXPECT_EQ(edit_distance("trakc", "track"), 1u);  // two neighbours swapped
  EXPECT_EQ(edit_distance("trick", "track"), 1u);  // a substitution
  EXPECT_EQ(edit_distance("", "run"), 3u);
  EXPECT_EQ(edit_distance("ekf", "opf"), 2u);
}

TEST(ClosestName, SuggestsANearMissOnly) {
  const std::vector<std::string> commands = {"track", "evaluate", "reproduce", "run", "render"};
  EXPECT_EQ(closest_name("trak", commands), "track");
  EXPECT_EQ(closest_name("evalute", commands), "evaluate");
  EXPECT_EQ(closest_name("rnu", commands), "run");
  EXPECT_EQ(closest_name("frobnicate", commands), std::nullopt);
  // Two edits of a three-letter name is most of it: no suggestion.
  EXPECT_EQ(closest_name("ekf", {"opf", "pf", "cvkf"}), std::nullopt);
  EXPECT_EQ(closest_name("imn", {"opf", "pf", "cvkf", "imm"}), "imm");
  EXPECT_EQ(closest_name("x", {}), std::nullopt);
}

TEST(ClosestName, APrefixOfALongerNameIsANearMiss) {
  EXPECT_EQ(closest_name("observation", {"observation-noise-translation", "seed"}),
            "observation-noise-translation");
  EXPECT_EQ(closest_name("particle", {"particles", "preset"}), "particles");
}

}  // namespace
}  // namespace opf
