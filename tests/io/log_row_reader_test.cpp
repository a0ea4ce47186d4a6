// Logs of one object without an object column: TUM trajectories ('#' comments, fields separated
// by spaces or tabs) and a CSV given the object's name; and the column mappings that would read
// one column as two fields.

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

MeasurementLog parse(const std::string& text, const LogReadOptions& options) {
  std::istringstream in(text);
  return parse_measurement_log(in, "traj.txt", options);
}

InputError parse_error(const std::string& text, const LogReadOptions& options) {
  try {
    parse(text, options);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", 0, "", "");
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
