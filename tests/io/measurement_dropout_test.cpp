#include "opf/io/measurement_dropout.h"

#include "opf/io/csv.h"
#include "opf/io/input_error.h"
#include "opf/io/measurement_log.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace opf {
namespace {

TEST(MeasurementDropout, WindowsAreHalfOpenAtFrameTimes) {
  const DropoutWindows windows{1.0, 2.0, 0.3};
  // 30 Hz: frames 30..38 (t = 1.0 .. 1.2667) and 90..98 are in, 29, 39, 89 and 99 are not.
  std::vector<int> in;
  for (int k = 0; k < 120; ++k)
    if (in_dropout_window(k / 30.0, windows)) in.push_back(k);
  EXPECT_EQ(in, (std::vector<int>{30, 31, 32, 33, 34, 35, 36, 37, 38, 90, 91, 92, 93, 94, 95, 96,
                                  97, 98}));
  // 10 Hz: t = 1.0, 1.1, 1.2 and 3.0, 3.1, 3.2; 1.3 = 13 / 10.0 lies on the window's end.
  std::vector<int> tenths;
  for (int k = 0; k < 40; ++k)
    if (in_dropout_window(k / 10.0, windows)) tenths.push_back(k);
  EXPECT_EQ(tenths, (std::vector<int>{10, 11, 12, 30, 31, 32}));
  EXPECT_FALSE(in_dropout_window(0.999, windows));
  EXPECT_TRUE(in_dropout_window(1.0 - 1e-12, windows));  // on the edge within the tolerance
  EXPECT_TRUE(in_dropout_window(201.0, windows));        // k = 100
  EXPECT_FALSE(in_dropout_window(201.3, windows));
  // A start long before the log keeps its phase: t - start kept no digit of t, so rows fell in
  // or out alike. -1e300 is a whole number of 2 s periods (windows from t = 0), 1 - 2e15 s one
  // more than that (windows from t = 1, as above).
  const DropoutWindows early{-1e300, 2.0, 0.3}, from_zero{0.0, 2.0, 0.3};
  const DropoutWindows also_early{1.0 - 2e15, 2.0, 0.3};
  for (int k = 0; k < 120; ++k) {
    EXPECT_EQ(in_dropout_window(k / 30.0, early), in_dropout_window(k / 30.0, from_zero)) << k;
    EXPECT_EQ(in_dropout_window(k / 30.0, also_early), in_dropout_window(k / 30.0, windows)) << k;
  }
}

TEST(MeasurementDropout, RejectsWindowsThatCannotBeMeant) {
  EXPECT_THROW(check_dropout_windows({1.0, 2.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(check_dropout_windows({1.0, 2.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(check_dropout_windows({1.0, 0.0, 0.3}), std::invalid_argument);
  EXPECT_THROW(check_dropout_windows({std::numeric_limits<double>::infinity(), 2.0, 0.3}),
               std::invalid_argument);
  EXPECT_NO_THROW(check_dropout_windows({-5.0, 2.0, 1.9}));
}

const std::string kLog =
    "t,object,x,y,z,qx,qy,qz,qw,source\n"
    "0.9,box,1,2,3,0,0,0,1,cam\n"
    "0.9,cup,4,5,6,0,0,0,1,cam\n"
    "1.0,box,1.5,2,3,0,0,0,1,cam\n"
    "1.0,cup,4.5,5,6,0,0,0,1,\"a, b\"\n"
    "1.1,box,,,,,,,,cam\n"
    "1.2,cup,4.6,5,6,0,0,0.6,0.8,cam\n"
    "1.3,box,1.7,2,3,0,0,0,1,cam\n";

TEST(MeasurementDropout, BlanksExactlyTheChosenRowsAndCopiesTheRest) {
  std::istringstream in(kLog);
  std::ostringstream out;
  const DropoutCounts counts = apply_dropout(in, "log.csv", out, {"box"}, {1.0, 2.0, 0.3});
  EXPECT_EQ(counts.rows, 7u);
  EXPECT_EQ(counts.blanked, 1u);  // box at 1.0; at 1.1 it had no pose already; 1.3 is outside
  EXPECT_EQ(out.str(),
            "t,object,x,y,z,qx,qy,qz,qw,source\n"
            "0.9,box,1,2,3,0,0,0,1,cam\n"
            "0.9,cup,4,5,6,0,0,0,1,cam\n"
            "1.0,box,,,,,,,,cam\n"
            "1.0,cup,4.5,5,6,0,0,0,1,\"a, b\"\n"
            "1.1,box,,,,,,,,cam\n"
            "1.2,cup,4.6,5,6,0,0,0.6,0.8,cam\n"
            "1.3,box,1.7,2,3,0,0,0,1,cam\n");

  // Every object when none is named; the result reads as a log with the same frames.
  std::istringstream again(kLog);
  std::ostringstream all;
  EXPECT_EQ(apply_dropout(again, "log.csv", all, {}, {1.0, 2.0, 0.3}).blanked, 3u);
  std::istringstream written(all.str());
  const MeasurementLog log = parse_measurement_log(written, "out.csv");
  ASSERT_EQ(log.frames.size(), 5u);  // t = 0.9 .. 1.3: blanked rows keep their frames
  EXPECT_EQ(log.frames[0].detections.size(), 2u);
  EXPECT_TRUE(log.frames[1].detections.empty());
  EXPECT_TRUE(log.frames[3].detections.empty());
  EXPECT_EQ(log.frames[4].detections.size(), 1u);
}

// A log of positions alone: its three fields blanked, and it stays one.
TEST(MeasurementDropout, BlanksALogOfPositionsAlone) {
  std::istringstream in("t,object,x,y,z\n0.9,box,1,2,3\n1.0,box,1.5,2,3\n1.3,box,1.7,2,3\n");
  std::ostringstream out;
  EXPECT_EQ(apply_dropout(in, "log.csv", out, {"box"}, {1.0, 2.0, 0.3}).blanked, 1u);
  EXPECT_EQ(out.str(), "t,object,x,y,z\n0.9,box,1,2,3\n1.0,box,,,\n1.3,box,1.7,2,3\n");
  std::istringstream written(out.str());
  const MeasurementLog log = parse_measurement_log(written, "out.csv");
  EXPECT_FALSE(log.states_orientation);
  ASSERT_EQ(log.frames.size(), 3u);
  EXPECT_TRUE(log.frames[1].detections.empty());
  // Some of the quaternion's columns without the others: refused, as the tracker refuses them.
  std::istringstream partial("t,object,x,y,z,qw\n0.9,box,1,2,3,1\n");
  try {
    apply_dropout(partial, "log.csv", out, {"box"}, {1.0, 2.0, 0.3});
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 1u);
    EXPECT_NE(e.message().find("missing required columns 'qx', 'qy', 'qz'"), std::string::npos)
        << e.what();
  }
}

TEST(MeasurementDropout, ErrorsNameTheLog) {
  std::istringstream in(kLog);
  std::ostringstream out;
  try {
    apply_dropout(in, "log.csv", out, {"box", "ball"}, {1.0, 2.0, 0.3});
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "log.csv");
    EXPECT_NE(e.message().find("'ball'"), std::string::npos) << e.what();
  }
  // An object named twice is dropped once (it was reported as having no row).
  std::istringstream twice_in(kLog);
  std::ostringstream twice_out;
  EXPECT_EQ(apply_dropout(twice_in, "log.csv", twice_out, {"box", "box"}, {1.0, 2.0, 0.3}).blanked,
            1u);
  std::istringstream bad("t,object,x,y,z,qx,qy,qz,qw\nnope,box,1,2,3,0,0,0,1\n");
  try {
    apply_dropout(bad, "bad.csv", out, {}, {1.0, 2.0, 0.3});
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.csv");
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.field(), "t");
  }
}

}  // namespace
}  // namespace opf
