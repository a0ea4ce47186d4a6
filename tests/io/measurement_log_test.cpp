#include "opf/io/measurement_log.h"

#include "opf/core/pose_conversion.h"
#include "opf/io/csv.h"
#include "opf/io/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>

namespace opf {
namespace {

constexpr const char* kHeader = "t,object,x,y,z,qx,qy,qz,qw\n";

MeasurementLog parse(const std::string& text) {
  std::istringstream in(text);
  return parse_measurement_log(in, "log.csv");
}

/// The InputError `text` must raise; fails the test (and returns an empty error) when none.
InputError parse_error(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("", 0, "", "");
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(MeasurementLog, GroupsUnsortedRowsIntoFramesOfIncreasingTime) {
  const MeasurementLog log = parse(std::string(kHeader) +
                                   "0.1,mug,4,5,6,0,0,0,1\n"
                                   "0.0,ball,1,2,3,0,0,0,1\n"
                                   "0.1,ball,1.5,2,3,0,0,0,1\n"
                                   "0.0,mug,4,5,6,0,0,0,1\n");
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[0].t, 0.0);
  EXPECT_EQ(log.frames[1].t, 0.1);
  ASSERT_EQ(log.frames[0].detections.size(), 2u);
  EXPECT_EQ(log.frames[0].detections[0].object, "ball");
  EXPECT_EQ(log.frames[0].detections[1].object, "mug");
  // Row order is kept within a frame.
  ASSERT_EQ(log.frames[1].detections.size(), 2u);
  EXPECT_EQ(log.frames[1].detections[0].object, "mug");
  EXPECT_EQ(log.frames[1].detections[1].object, "ball");
  EXPECT_EQ(log.frames[1].find("ball")->pose.x(), 1.5);
  EXPECT_EQ(log.objects, (std::vector<std::string>{"ball", "mug"}));
}

TEST(MeasurementLog, ReadsPoseAsTranslationAndXyzwQuaternion) {
  const double s = std::sqrt(0.5);  // 90 degrees about z
  const MeasurementLog log = parse(std::string(kHeader) + "2.5,box,0.1,-0.2,0.3,0,0," +
                                   std::to_string(s) + "," + std::to_string(s) + "\n");
  ASSERT_EQ(log.frames.size(), 1u);
  const auto& pose = log.frames[0].detections.at(0).pose;
  EXPECT_EQ(pose.x(), 0.1);
  EXPECT_EQ(pose.y(), -0.2);
  EXPECT_EQ(pose.z(), 0.3);
  EXPECT_NEAR(pose.yaw(), std::numbers::pi / 2, 1e-6);
  EXPECT_NEAR(pose.pitch(), 0.0, 1e-9);
  EXPECT_NEAR(pose.roll(), 0.0, 1e-9);
}

// A detector of positions alone: no quaternion column, every orientation the identity (as a
// MOTChallenge box's), an object unobserved where its three fields are empty.
TEST(MeasurementLog, ReadsALogOfPositionsAloneWithTheIdentityOrientation) {
  const MeasurementLog log = parse(
      "t,object,x,y,z,radius\n0,ball,0.1,-0.2,0.3,0.02\n0,mug,1,2,3,\n0.1,ball,,,,\n"
      "0.1,mug,1.5,2,3,\n");
  EXPECT_FALSE(log.states_orientation);
  ASSERT_EQ(log.frames.size(), 2u);
  ASSERT_EQ(log.frames[0].detections.size(), 2u);
  const Detection& ball = log.frames[0].detections[0];
  EXPECT_EQ(ball.pose.x(), 0.1);
  EXPECT_EQ(ball.pose.y(), -0.2);
  EXPECT_EQ(ball.pose.z(), 0.3);
  EXPECT_EQ(ball.radius, 0.02);
  for (const Frame& frame : log.frames)
    for (const Detection& detection : frame.detections)
      EXPECT_EQ(orientation_of(detection.pose).coeffs(), Eigen::Quaterniond::Identity().coeffs());
  EXPECT_EQ(log.frames[1].find("ball"), nullptr);
  EXPECT_EQ(log.frames[1].find("mug")->pose.x(), 1.5);
  EXPECT_TRUE(parse(std::string(kHeader) + "0,ball,0,0,0,0,0,0,1\n").states_orientation);

  std::istringstream in("t,object,x,y,z\n0,ball,0,0,0\n");
  EXPECT_FALSE(MeasurementStream(in, "log.csv").states_orientation());
}

TEST(MeasurementLogErrors, APartlyEmptyPositionInALogOfPositions) {
  const InputError e = parse_error("t,object,x,y,z\n0,ball,1,,3\n");
  EXPECT_STREQ(e.what(),
               "log.csv:2: column 'y': empty while other position fields are set; leave all "
               "three of x,y,z empty to mark the object unobserved");
}

// Some of the quaternion's columns, or --columns naming them in a file that has none: a mistake,
// not a log of positions.
TEST(MeasurementLogErrors, AnOrientationWantsAllFourColumns) {
  InputError e = parse_error("t,object,x,y,z,qw\n0,ball,1,2,3,1\n");
  EXPECT_STREQ(e.what(),
               "log.csv:1: missing required columns 'qx', 'qy', 'qz' (the header has 't', "
               "'object', 'x', 'y', 'z', 'qw'); qx,qy,qz,qw come together: all of them or none");
  LogReadOptions renamed;
  renamed.columns = {{"qw", "rw"}};
  std::istringstream in("t,object,x,y,z\n0,ball,1,2,3\n");
  try {
    parse_measurement_log(in, "log.csv", renamed);
    ADD_FAILURE() << "a renamed quaternion column that the file lacks was read as positions";
  } catch (const InputError& error) {
    EXPECT_TRUE(error.message().starts_with("missing required columns 'qx', 'qy', 'qz', 'rw' ("))
        << error.what();
  }
  e = parse_error("t,object,x,y,z,qx,qy,qz,qw,qx\n0,ball,1,2,3,0,0,0,1,0\n");
  EXPECT_STREQ(e.what(), "log.csv:1: column 'qx' appears more than once in the header");
}

TEST(MeasurementLog, AcceptsAnyColumnOrderAndIgnoresExtraColumns) {
  const MeasurementLog log = parse(
      "qw,source,object,t,note,z,y,x,qx,qy,qz\n"
      "1,sim,ball,0.5,whatever,3,2,1,0,0,0\n");
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].t, 0.5);
  const auto& pose = log.frames[0].find("ball")->pose;
  EXPECT_EQ(pose.x(), 1.0);
  EXPECT_EQ(pose.y(), 2.0);
  EXPECT_EQ(pose.z(), 3.0);
}

TEST(MeasurementLog, ToleratesBomCrlfBlankLinesPaddingAndQuotes) {
  const MeasurementLog log = parse(
      "\xEF\xBB\xBF t , object ,x,y,z,qx,qy,qz,qw\r\n"
      "\r\n"
      "  0.25 , \"red, cup\" , 1 ,2,3, 0,0,0,1 \r\n"
      "\t\r\n"
      "\"0.5\",ball,\"1\",2,3,0,0,0,1\r\n");
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[0].t, 0.25);
  ASSERT_NE(log.frames[0].find("red, cup"), nullptr);
  EXPECT_EQ(log.frames[0].find("red, cup")->pose.x(), 1.0);
  EXPECT_EQ(log.frames[1].t, 0.5);
  EXPECT_EQ(log.objects, (std::vector<std::string>{"red, cup", "ball"}));
}

TEST(MeasurementLog, ReadsEachDetectionsStatedExtraNoise) {
  // The optional column, in any place; empty (or absent) states none.
  const MeasurementLog log = parse(
      "t,object,extra_noise,x,y,z,qx,qy,qz,qw\n"
      "0,ball,0.0125,0.1,0.2,0.3,0,0,0,1\n"
      "0,mug,,0.5,0,0,0,0,0,1\n");
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].find("ball")->extra_noise, 0.0125);
  EXPECT_EQ(log.frames[0].find("mug")->extra_noise, 0.0);
  EXPECT_EQ(
      parse(std::string(kHeader) + "0,ball,0,0,0,0,0,0,1\n").frames[0].detections[0].extra_noise,
      0.0);
}

TEST(MeasurementLog, TheExtraNoiseIsInTheLogsLengthUnit) {
  LogReadOptions millimetres;
  millimetres.length_unit = LengthUnit::kMillimetres;
  std::istringstream in("t,object,x,y,z,qx,qy,qz,qw,extra_noise\n0,ball,100,0,0,0,0,0,1,20\n");
  const MeasurementLog log = parse_measurement_log(in, "log.csv", millimetres);
  EXPECT_DOUBLE_EQ(log.frames[0].detections[0].extra_noise, 0.02);
}

TEST(MeasurementLogErrors, ANegativeOrNonNumericExtraNoise) {
  InputError e = parse_error(
      "t,object,x,y,z,qx,qy,qz,qw,extra_noise\n0,ball,0,0,0,0,0,0,1,0\n"
      "1,ball,0,0,0,0,0,0,1,-0.01\n");
  EXPECT_STREQ(e.what(),
               "log.csv:3: column 'extra_noise': expected a standard deviation >= 0, got -0.01");
  e = parse_error("t,object,x,y,z,qx,qy,qz,qw,extra_noise\n0,ball,0,0,0,0,0,0,1,wide\n");
  EXPECT_EQ(e.field(), "extra_noise");
  EXPECT_EQ(e.line(), 2u);
}

// Past 1e6 m (kMaxNoise, as for a setting) the filters' estimates turn into NaN; the limit is in
// metres whatever the log's unit.
TEST(MeasurementLogErrors, AnExtraNoisePastTheLimit) {
  const InputError e = parse_error(
      "t,object,x,y,z,qx,qy,qz,qw,extra_noise\n0,ball,0,0,0,0,0,0,1,1000000\n"
      "1,ball,0,0,0,0,0,0,1,1e300\n");
  EXPECT_STREQ(e.what(),
               "log.csv:3: column 'extra_noise': expected a standard deviation up to 1e+06 m, got "
               "1e300");
  LogReadOptions millimetres;
  millimetres.length_unit = LengthUnit::kMillimetres;
  std::istringstream at_limit("t,object,x,y,z,qx,qy,qz,qw,extra_noise\n0,ball,0,0,0,0,0,0,1,1e9\n");
  EXPECT_EQ(
      parse_measurement_log(at_limit, "log.csv", millimetres).frames[0].detections[0].extra_noise,
      1e6);
  std::istringstream past("t,object,x,y,z,qx,qy,qz,qw,extra_noise\n0,ball,0,0,0,0,0,0,1,2e9\n");
  EXPECT_THROW(parse_measurement_log(past, "log.csv", millimetres), InputError);
}

TEST(MeasurementLog, ReadsEachDetectionsStatedRadiusInTheLogsLengthUnit) {
  const MeasurementLog log = parse(
      "t,object,x,y,z,qx,qy,qz,qw,radius\n"
      "0,ball,0.1,0.2,0.3,0,0,0,1,0.025\n"
      "0,mug,0.5,0,0,0,0,0,1,\n");
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].find("ball")->radius, 0.025);
  EXPECT_EQ(log.frames[0].find("mug")->radius, 0.0);  // empty: not stated
  LogReadOptions millimetres;
  millimetres.length_unit = LengthUnit::kMillimetres;
  std::istringstream in("t,object,x,y,z,qx,qy,qz,qw,radius\n0,ball,100,0,0,0,0,0,1,45\n");
  EXPECT_DOUBLE_EQ(parse_measurement_log(in, "log.csv", millimetres).frames[0].detections[0].radius,
                   0.045);
}

TEST(MeasurementLogErrors, ANegativeOrNonNumericRadius) {
  InputError e = parse_error("t,object,x,y,z,qx,qy,qz,qw,radius\n0,ball,0,0,0,0,0,0,1,-0.02\n");
  EXPECT_STREQ(e.what(), "log.csv:2: column 'radius': expected a radius >= 0, got -0.02");
  e = parse_error("t,object,x,y,z,qx,qy,qz,qw,radius\n0,ball,0,0,0,0,0,0,1,big\n");
  EXPECT_EQ(e.field(), "radius");
  EXPECT_EQ(e.line(), 2u);
}

TEST(MeasurementLog, ReadsEachDetectionsStatedBoxInTheLogsLengthUnit) {
  const MeasurementLog log = parse(
      "t,object,x,y,z,qx,qy,qz,qw,radius,box_x,box_y,box_z\n"
      "0,hand,0.1,0.2,0.3,0,0,0,1,0.079,0.14,0.12,0.04\n"
      "0,ball,0.5,0,0,0,0,0,1,0.025,,,\n");
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].find("hand")->box, Eigen::Vector3d(0.14, 0.12, 0.04));
  EXPECT_EQ(log.frames[0].find("ball")->box, Eigen::Vector3d::Zero());  // empty: not stated
  LogReadOptions millimetres;
  millimetres.length_unit = LengthUnit::kMillimetres;
  std::istringstream in(
      "t,object,x,y,z,qx,qy,qz,qw,box_x,box_y,box_z\n0,hand,0,0,0,0,0,0,1,140,"
      "120,40\n");
  EXPECT_TRUE(parse_measurement_log(in, "log.csv", millimetres)
                  .frames[0]
                  .detections[0]
                  .box.isApprox(Eigen::Vector3d(0.14, 0.12, 0.04)));
}

// A box is stated by its three extents together, each > 0; the error names the file, line and
// column.
TEST(MeasurementLogErrors, AnIncompleteOrNonPositiveBox) {
  InputError e = parse_error("t,object,x,y,z,qx,qy,qz,qw,box_x,box_z\n0,hand,0,0,0,0,0,0,1,1,1\n");
  EXPECT_STREQ(e.what(),
               "log.csv:1: column 'box_y': missing: a box is stated by box_x, box_y and box_z "
               "together");
  e = parse_error("t,object,x,y,z,qx,qy,qz,qw,box_x,box_y,box_z\n0,hand,0,0,0,0,0,0,1,0.1,,0.1\n");
  EXPECT_EQ(e.field(), "box_y");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_NE(std::string(e.what()).find("leave all three empty"), std::string::npos);
  e = parse_error("t,object,x,y,z,qx,qy,qz,qw,box_x,box_y,box_z\n0,hand,0,0,0,0,0,0,1,0.1,0.1,0\n");
  EXPECT_STREQ(e.what(), "log.csv:2: column 'box_z': expected a box's extent > 0, got 0");
}

TEST(MeasurementLog, EmptyPoseRowMarksObjectUnobservedButKeepsTheFrame) {
  const MeasurementLog log = parse(std::string(kHeader) +
                                   "0,ball,1,2,3,0,0,0,1\n"
                                   "1,ball,,,,,,,\n"
                                   "2,ghost, , ,,,,,\n"
                                   "2,ball,1,2,3,0,0,0,1\n");
  ASSERT_EQ(log.frames.size(), 3u);
  EXPECT_EQ(log.frames[1].t, 1.0);
  EXPECT_TRUE(log.frames[1].detections.empty());
  EXPECT_EQ(log.frames[2].find("ghost"), nullptr);
  EXPECT_NE(log.frames[2].find("ball"), nullptr);
  // Never detected, so not an object of the log.
  EXPECT_EQ(log.objects, (std::vector<std::string>{"ball"}));
}

// Nothing to track is refused, naming the file: a header only, or rows that are all unobserved.
TEST(MeasurementLog, ALogWithoutDetectionsIsRefused) {
  for (const std::string& text :
       {std::string(kHeader), std::string(kHeader) + "0,ball,,,,,,,\n1,ball,,,,,,,\n"}) {
    const InputError e = parse_error(text);
    EXPECT_EQ(e.file(), "log.csv");
    EXPECT_TRUE(contains(e.message(), "no detections")) << e.what();
  }
}

// A log written with another delimiter is named as such, not as a missing header.
TEST(MeasurementLog, AnotherDelimiterIsNamed) {
  InputError e = parse_error("t;object;x;y;z;qx;qy;qz;qw\n0;ball;0;0;0;0;0;0;1\n");
  EXPECT_EQ(e.line(), 1u);
  EXPECT_TRUE(contains(e.message(), "the header is separated by ';'")) << e.what();
  EXPECT_FALSE(contains(e.message(), "header line missing")) << e.what();
  e = parse_error("t\tobject\tx\ty\tz\tqx\tqy\tqz\tqw\n");
  EXPECT_TRUE(contains(e.message(), "the header is separated by tabs")) << e.what();
  // A header-less log still gets the other hint.
  e = parse_error("0,ball,0,0,0,0,0,0,1\n");
  EXPECT_TRUE(contains(e.message(), "is the header line missing?")) << e.what();
}

TEST(MeasurementLog, ListsObjectsByFirstDetectionInTime) {
  const MeasurementLog log = parse(std::string(kHeader) +
                                   "1,late,0,0,0,0,0,0,1\n"
                                   "0,early,,,,,,,\n"
                                   "0.5,early,0,0,0,0,0,0,1\n");
  EXPECT_EQ(log.objects, (std::vector<std::string>{"early", "late"}));
}

TEST(MeasurementLog, NormalisesNearlyUnitQuaternions) {
  // (0, 0, 0.6, 0.8) scaled by 1.005.
  const MeasurementLog log = parse(std::string(kHeader) + "0,ball,0,0,0,0,0,0.603,0.804\n");
  const auto q = orientation_of(log.frames[0].detections.at(0).pose);
  EXPECT_NEAR(std::abs(q.z()), 0.6, 1e-12);
  EXPECT_NEAR(std::abs(q.w()), 0.8, 1e-12);
}

TEST(MeasurementLog, ComparesTimesAsNumbers) {
  const MeasurementLog log = parse(std::string(kHeader) +
                                   "0.50,ball,0,0,0,0,0,0,1\n"
                                   "5e-1,mug,0,0,0,0,0,0,1\n");
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].detections.size(), 2u);
}

TEST(MeasurementLogErrors, EmptyFileOrNoHeader) {
  for (const std::string text : {"", "\n  \r\n", "\xEF\xBB\xBF"}) {
    const InputError e = parse_error(text);
    EXPECT_EQ(e.file(), "log.csv");
    EXPECT_EQ(e.line(), 0u);
    EXPECT_EQ(e.message(),
              "empty file: expected a header line with the columns t,object,x,y,z and, all or "
              "none, qx,qy,qz,qw");
  }
  const InputError e = parse_error("0,ball,1,2,3,0,0,0,1\n");
  EXPECT_EQ(e.line(), 1u);
  EXPECT_TRUE(contains(e.message(), "header line missing")) << e.what();
}

// A file without line breaks (a binary file, a mangled export) stops at the first line longer
// than 1 MiB instead of being read into memory whole; a line just under the bound is read.
TEST(MeasurementLogErrors, ALineLongerThanTheBoundIsAnErrorNotAnAllocation) {
  const std::string row = "0,ball,0,0,0,0,0,0,1";
  const std::string padded_header =
      "t,object,x,y,z,qx,qy,qz,qw" + std::string(csv::kMaxLineBytes - 26 - 8, ' ') + ",comment\n";
  ASSERT_EQ(padded_header.size(), csv::kMaxLineBytes + 1);  // the longest line, and its '\n'
  EXPECT_EQ(parse(padded_header + row + ",x\n").frames.size(), 1u);

  const InputError e =
      parse_error(std::string(kHeader) + row + "\n" + std::string(3 * csv::kMaxLineBytes, 'x'));
  EXPECT_EQ(e.line(), 3u);
  EXPECT_TRUE(contains(e.message(), "line longer than 1048576 bytes")) << e.what();
}

// A long log (200 000 rows of 4 objects, 50 000 frames) is read in full, row for row.
TEST(MeasurementLog, ReadsALongLogInFull) {
  std::string text = kHeader;
  constexpr int kFrames = 50'000;
  for (int k = 0; k < kFrames; ++k)
    for (const char* object : {"a", "b", "c", "d"})
      text += std::to_string(k) + "e-2," + object + ",1,2,3,0,0,0,1\n";
  const MeasurementLog log = parse(text);
  ASSERT_EQ(log.frames.size(), static_cast<std::size_t>(kFrames));
  EXPECT_EQ(log.objects.size(), 4u);
  for (const Frame& frame : log.frames) ASSERT_EQ(frame.detections.size(), 4u) << frame.t;
  EXPECT_DOUBLE_EQ(log.frames.back().t, (kFrames - 1) * 1e-2);
}

TEST(MeasurementLogErrors, MissingColumnsAreListed) {
  const InputError e = parse_error("\n\nt,object,x,y,z,qx,qy\n0,ball,0,0,0,0,0\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.message(),
            "missing required columns 'qz', 'qw' (the header has 't', 'object', 'x', 'y', 'z', "
            "'qx', 'qy'); qx,qy,qz,qw come together: all of them or none");
}

TEST(MeasurementLogErrors, WrongNumberOfFields) {
  const InputError e = parse_error(std::string(kHeader) +
                                   "0,ball,0,0,0,0,0,0,1\n"
                                   "1,ball,0,0,0,0,0,0,1,extra\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "");
  EXPECT_TRUE(contains(e.message(), "expected 9 fields")) << e.what();
  EXPECT_TRUE(contains(e.message(), "got 10")) << e.what();
}

TEST(MeasurementLogErrors, EmptyObjectName) {
  const InputError e = parse_error(std::string(kHeader) + "0, ,0,0,0,0,0,0,1\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "object");
}

TEST(MeasurementLogErrors, NonNumericField) {
  const InputError e =
      parse_error(std::string(kHeader) + "0,ball,0,0,0,0,0,0,1\n\n" + "1,ball,0,0,0,0,0,0,abc\n");
  EXPECT_STREQ(e.what(), "log.csv:4: column 'qw': expected a number, got \"abc\"");
  EXPECT_EQ(e.file(), "log.csv");
  EXPECT_EQ(e.line(), 4u);
  EXPECT_EQ(e.field(), "qw");
}

TEST(MeasurementLogErrors, TrailingGarbageInANumber) {
  const InputError e = parse_error(std::string(kHeader) + "0,ball,0.5m,0,0,0,0,0,1\n");
  EXPECT_EQ(e.field(), "x");
  EXPECT_EQ(e.line(), 2u);
}

TEST(MeasurementLogErrors, NanAndInfinityAreRejected) {
  const InputError nan = parse_error(std::string(kHeader) + "0,ball,0,0,0,0,0,nan,1\n");
  EXPECT_EQ(nan.field(), "qz");
  EXPECT_TRUE(contains(nan.message(), "finite")) << nan.what();
  const InputError inf = parse_error(std::string(kHeader) + "0,ball,0,-inf,0,0,0,0,1\n");
  EXPECT_EQ(inf.field(), "y");
  const InputError t = parse_error(std::string(kHeader) + "inf,ball,0,0,0,0,0,0,1\n");
  EXPECT_EQ(t.field(), "t");
  EXPECT_EQ(t.line(), 2u);
}

TEST(MeasurementLogErrors, EmptyTime) {
  const InputError e = parse_error(std::string(kHeader) + ",ball,,,,,,,\n");
  EXPECT_EQ(e.field(), "t");
}

TEST(MeasurementLogErrors, PartlyEmptyPose) {
  const InputError e = parse_error(std::string(kHeader) + "0,ball,1,2,3,,0,0,1\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "qx");
  EXPECT_TRUE(contains(e.message(), "all seven")) << e.what();
}

TEST(MeasurementLogErrors, QuaternionFarFromUnitNorm) {
  const InputError e =
      parse_error(std::string(kHeader) + "0,ball,0,0,0,0,0,0,1\n" + "1,ball,0,0,0,0,0,0,1.02\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "qx,qy,qz,qw");
  EXPECT_TRUE(contains(e.message(), "1.02")) << e.what();
  EXPECT_THROW(parse(std::string(kHeader) + "0,ball,0,0,0,0,0,0,0\n"), InputError);
  EXPECT_NO_THROW(parse(std::string(kHeader) + "0,ball,0,0,0,0,0,0,1.0099\n"));
}

TEST(MeasurementLogErrors, SameObjectTwiceAtOneTime) {
  const InputError e = parse_error(std::string(kHeader) +
                                   "0.5,ball,0,0,0,0,0,0,1\n"
                                   "0.5,mug,0,0,0,0,0,0,1\n"
                                   "0.50,ball,,,,,,,\n");
  EXPECT_EQ(e.line(), 4u);
  EXPECT_EQ(e.field(), "object");
  EXPECT_TRUE(contains(e.message(), "first on line 2")) << e.what();
}

TEST(MeasurementLogErrors, UnterminatedQuote) {
  const InputError e = parse_error(std::string(kHeader) + "0,\"ball,0,0,0,0,0,0,1\n");
  EXPECT_EQ(e.line(), 2u);
}

TEST(MeasurementLogErrors, MissingFile) {
  const std::filesystem::path path = "/nonexistent/dir/log.csv";
  try {
    read_measurement_log(path);
    FAIL() << "no error for a missing file";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_EQ(e.line(), 0u);
    EXPECT_TRUE(contains(e.what(), "not found")) << e.what();
  }
  EXPECT_THROW(read_measurement_log(std::filesystem::temp_directory_path()), InputError);
}

TEST(MeasurementLogExample, HasTheDocumentedScenario) {
  const std::filesystem::path data = std::filesystem::path(OPF_SOURCE_DIR) / "experiments" / "data";
  const MeasurementLog log = read_measurement_log(data / "example_log.csv");
  const MeasurementLog truth = read_measurement_log(data / "example_truth.csv");
  ASSERT_EQ(log.frames.size(), 180u);
  ASSERT_EQ(truth.frames.size(), 180u);
  EXPECT_EQ(log.objects, (std::vector<std::string>{"ball", "mug"}));

  std::size_t mug_frames = 0;
  for (std::size_t k = 0; k < log.frames.size(); ++k) {
    const Frame& frame = log.frames[k];
    EXPECT_NEAR(frame.t, static_cast<double>(k) / 30.0, 1e-6);
    EXPECT_EQ(truth.frames[k].t, frame.t);
    const bool occluded = frame.t >= 2.0 && frame.t < 3.0;
    EXPECT_EQ(frame.find("ball") == nullptr, occluded) << "t = " << frame.t;
    if (frame.find("mug") != nullptr) ++mug_frames;
    for (const Detection& detection : frame.detections) {
      const Detection* true_pose = truth.frames[k].find(detection.object);
      ASSERT_NE(true_pose, nullptr);
      // Measurement noise is 0.005 m and 0.02 rad per axis: 6 sigma bounds.
      EXPECT_LT((translation_of(detection.pose) - translation_of(true_pose->pose)).norm(), 0.06);
      EXPECT_LT(orientation_of(detection.pose).angularDistance(orientation_of(true_pose->pose)),
                0.25);
    }
  }
  EXPECT_EQ(mug_frames, 171u);  // 5% of 180 frames missed
  for (const Frame& frame : truth.frames) EXPECT_EQ(frame.detections.size(), 2u);
}

}  // namespace
}  // namespace opf
