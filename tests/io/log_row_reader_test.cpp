// Logs in other shapes: TUM trajectories ('#' comments, fields separated by spaces or tabs) and a
// CSV given the object's name, both of one object without an object column; MOTChallenge boxes;
// and the column mappings that would read one column as two fields.

#include "io/parse_log.h"
#include "opf/io/input_error.h"
#include "opf/io/measurement_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

namespace opf {
namespace {

LogReadOptions tum(const std::string& object) {
  LogReadOptions options;
  options.format = LogFormat::kTum;
  options.object = object;
  return options;
}

TEST(TumLog, ReadsTimesPosesAndCommentsAsOneObject) {
  const MeasurementLog log = parse(
      "# ground truth\n"
      "# timestamp tx ty tz qx qy qz qw\n"
      "1403715273.000 0.1 0.2 0.3 0 0 0 1\n"
      "\n"
      "1403715273.100\t0.1  0.2 0.4 0 0 0.7071067811865476 0.7071067811865476\n",
      tum("room1"));
  ASSERT_EQ(log.objects, std::vector<std::string>{"room1"});
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_DOUBLE_EQ(log.frames[0].t, 1403715273.0);
  EXPECT_NEAR(log.frames[1].t - log.frames[0].t, 0.1, 1e-6);
  const Detection* second = log.frames[1].find("room1");
  ASSERT_NE(second, nullptr);
  EXPECT_DOUBLE_EQ(second->pose.z(), 0.4);
  EXPECT_NEAR(second->pose.yaw(), M_PI / 2, 1e-12);  // qz, qw: a quarter turn about z
}

TEST(TumLog, ErrorsNameTheFileLineAndField) {
  InputError e = parse_error("# c\n1 0.1 0.2 zero 0 0 0 1\n", tum("a"));
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "tz");
  e = parse_error("1 0.1 0.2 0.3 0 0 0 1\n2 0.1 0.2 0.3 0 0 1\n", tum("a"));
  EXPECT_EQ(e.line(), 2u);
  EXPECT_NE(e.message().find("expected 8 fields separated by spaces (timestamp tx ty tz qx qy qz "
                             "qw), got 7"),
            std::string::npos)
      << e.what();
  e = parse_error("1 0.1 0.2 0.3 0 0 0 2\n", tum("a"));
  EXPECT_NE(e.message().find("unit quaternion"), std::string::npos) << e.what();
}

LogReadOptions boxes(double rate) {
  LogReadOptions options;
  options.format = LogFormat::kMot;
  options.rate = rate;
  return options;
}

TEST(MotLog, BoxesBecomeTheirBottomCentresTimedByFrameNumber) {
  // gt.txt: frame, id, left, top, width, height, flag, class, visibility; flag 0 is not scored.
  const MeasurementLog log = parse(
      "1,7,100,200,40,80,1,1,0.9\n"
      "1,8,500,200,40,80,0,7,1.0\n"
      "2,7,104,200,40,80,1,1,0.8\n",
      boxes(25.0));
  ASSERT_EQ(log.objects, std::vector<std::string>{"7"});
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_DOUBLE_EQ(log.frames[1].t, 0.04);  // (2 - 1) / 25 Hz
  const mrpt::poses::CPose3D& foot = log.frames[1].find("7")->pose;
  EXPECT_DOUBLE_EQ(foot.x(), 0.124);  // (104 + 40 / 2) px at 1 mm per px
  EXPECT_DOUBLE_EQ(foot.y(), 0.280);  // 200 + 80: the bottom edge
  EXPECT_DOUBLE_EQ(foot.z(), 0.0);
  // A tracker's results (ten fields, a confidence in the seventh) keep every row.
  EXPECT_EQ(parse("1,3,10,20,4,8,0.2,-1,-1,-1\n", boxes(30.0)).objects,
            std::vector<std::string>{"3"});
}

TEST(MotLog, BoxesWithoutAnIdOrASizeAreRefusedByField) {
  InputError e = parse_error("1,-1,10,20,4,8,0.9,-1,-1,-1\n", boxes(30.0));  // det.txt
  EXPECT_EQ(e.field(), "id");
  EXPECT_NE(e.message().find("det.txt's boxes need associating first"), std::string::npos);
  e = parse_error("1,2,10,20,0,8,0.9,-1,-1,-1\n", boxes(30.0));
  EXPECT_EQ(e.field(), "bb_width");
  e = parse_error("0,2,10,20,4,8,0.9,-1,-1,-1\n", boxes(30.0));
  EXPECT_EQ(e.field(), "frame");
  e = parse_error("1,2,10,20,4,8\n", boxes(30.0));
  EXPECT_NE(e.message().find("expected at least 7 fields separated by commas (frame, id, bb_left, "
                             "bb_top, bb_width, bb_height, conf), got 6"),
            std::string::npos)
      << e.message();
  LogReadOptions no_rate = boxes(30.0);
  no_rate.rate.reset();
  EXPECT_THROW(parse("1,2,10,20,4,8,1,1,1\n", no_rate), std::invalid_argument);
}

TEST(OneObjectLog, ACsvWithoutAnObjectColumnTakesTheGivenName) {
  LogReadOptions options;
  options.object = "cup";
  const MeasurementLog log =
      parse("t,x,y,z,qx,qy,qz,qw\n0,1,2,3,0,0,0,1\n0.1,1,2,3,0,0,0,1\n", options);
  EXPECT_EQ(log.objects, std::vector<std::string>{"cup"});
  EXPECT_EQ(log.frames.size(), 2u);
  // With an object column as well, which object a row is of would be said twice: refused.
  const InputError e = parse_error("t,object,x,y,z,qx,qy,qz,qw\n0,a,1,2,3,0,0,0,1\n", options);
  EXPECT_EQ(e.field(), "object");
}

TEST(ColumnMapping, APoseColumnOntoAColumnStillReadAsItselfIsRefused) {
  EXPECT_THROW(parse_column_mapping("object=t"), std::invalid_argument);
  EXPECT_THROW(parse_column_mapping("t=x"), std::invalid_argument);
  // Renaming both is a swap, and reading another name is fine.
  EXPECT_EQ(parse_column_mapping("qx=qy,qy=qx").size(), 2u);
  EXPECT_EQ(parse_column_mapping("object=name").size(), 1u);
}

}  // namespace
}  // namespace opf
