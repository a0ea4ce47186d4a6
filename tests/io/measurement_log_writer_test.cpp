#include "opf/io/measurement_log_writer.h"

#include "opf/core/pose_conversion.h"
#include "opf/io/measurement_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace opf {
namespace {

TEST(MeasurementLogWriter, RoundTripsThroughTheReader) {
  std::ostringstream out;
  write_measurement_header(out);
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  write_measurement_row(out, 0.1, "box", {0.301, 0.122, 1.0053}, turned);
  // The same rotation with w < 0 is written with w >= 0.
  write_measurement_row(out, 0.2, "my, box", {1.0 / 3.0, 0.0, 2.0},
                        Eigen::Quaterniond(-turned.w(), -turned.x(), -turned.y(), -turned.z()));
  EXPECT_EQ(out.str().substr(0, out.str().find('\n')), "t,object,x,y,z,qx,qy,qz,qw");
  EXPECT_NE(out.str().find("0.2,\"my, box\",0.3333333333333333,0,2,0,0,"), std::string::npos)
      << out.str();
  std::istringstream in(out.str());
  const MeasurementLog log = parse_measurement_log(in, "written.csv");
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[0].t, 0.1);
  const Detection& box = log.frames[0].detections.at(0);
  EXPECT_EQ(box.object, "box");
  EXPECT_EQ(translation_of(box.pose), Eigen::Vector3d(0.301, 0.122, 1.0053));
  EXPECT_NEAR(orientation_of(box.pose).angularDistance(turned), 0.0, 1e-12);
  const Detection& other = log.frames[1].detections.at(0);
  EXPECT_EQ(other.object, "my, box");
  EXPECT_EQ(translation_of(other.pose).x(), 1.0 / 3.0);  // shortest exact text
  EXPECT_GE(orientation_of(other.pose).w(), 0.0);
  EXPECT_NEAR(orientation_of(other.pose).angularDistance(turned), 0.0, 1e-12);
}

}  // namespace
}  // namespace opf
