// A log written with w first is suspected; one written x, y, z, w is not.

#include "opf/io/quaternion_order_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

namespace opf {
namespace {

MeasurementLog parse(const std::string& text) {
  std::istringstream in(text);
  return parse_measurement_log(in, "log.csv", {});
}

TEST(QuaternionOrder, ALogWrittenWFirstIsSuspectedAndARightOneIsNot) {
  std::string right = "t,object,x,y,z,qx,qy,qz,qw\n", w_first = right;
  for (int k = 0; k < 12; ++k) {
    const double t = 0.1 * k, yaw = 0.3 + 0.01 * k;
    const std::string time = std::to_string(t) + ",mug,0.5,0.1,0.04,";
    const std::string s = std::to_string(std::sin(yaw / 2)), c = std::to_string(std::cos(yaw / 2));
    right += time + "0,0," + s + "," + c + "\n";
    w_first += time + c + ",0,0," + s + "\n";
  }
  EXPECT_TRUE(objects_with_w_first_quaternions(parse(right)).empty());
  EXPECT_EQ(objects_with_w_first_quaternions(parse(w_first)), std::vector<std::string>{"mug"});
  EXPECT_NE(w_first_warning("mug", LogFormat::kCsv).find("--columns qw=qx,qx=qy,qy=qz,qz=qw"),
            std::string::npos);
  EXPECT_EQ(w_first_warning("mug", LogFormat::kTum).find("--columns"), std::string::npos);
}

}  // namespace
}  // namespace opf
