// The pieces of the one options schema: admissible ranges and the checker's messages.

#include "opf/core/option_schema.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace opf {
namespace {

TEST(OptionSchema, BoundsAdmitFiniteValuesBetweenTheirLimits) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(positive().admits(1e-300));
  EXPECT_FALSE(positive().admits(0.0));
  EXPECT_FALSE(positive().admits(inf));
  EXPECT_FALSE(positive().admits(nan));
  EXPECT_TRUE(non_negative().admits(0.0));
  EXPECT_FALSE(non_negative().admits(-1e-300));
  EXPECT_TRUE(unit_fraction().admits(1.0));
  EXPECT_FALSE(unit_fraction().admits(0.0));
  EXPECT_FALSE(unit_fraction().admits(std::nextafter(1.0, 2.0)));
  EXPECT_TRUE(between(0, 5, "").admits(5.0));
  EXPECT_FALSE(between(0, 5, "").admits(6.0));
  EXPECT_FALSE(greater_than(1.0, "").admits(1.0));
  EXPECT_TRUE(at_least(1.0, "").admits(1.0));
}

struct Inner {
  double gain = 2.0;
};
struct Outer {
  int count = 3;
  Inner inner;
};
template <class Visitor>
void describe_options(Visitor& v, Outer& o) {
  v.integer("count", o.count, at_least(1, "a positive integer"));
  v.section("inner", [&] { v.number("gain", o.inner.gain, positive("a positive gain")); });
}

std::string message_of(const Outer& options) {
  try {
    check_options(options, "widget");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(OptionSchema, TheCheckerNamesTheKeyPathTheExpectationAndTheValue) {
  EXPECT_EQ(message_of(Outer{}), "");
  Outer bad;
  bad.inner.gain = -0.5;
  EXPECT_EQ(message_of(bad), "widget option inner.gain must be a positive gain, got -0.5");
  bad = {};
  bad.count = 0;
  EXPECT_EQ(message_of(bad), "widget option count must be a positive integer, got 0");
}

}  // namespace
}  // namespace opf
