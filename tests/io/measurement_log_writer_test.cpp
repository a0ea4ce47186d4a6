#include "opf/io/measurement_log_writer.h"

#include "opf/core/pose_conversion.h"
#include "opf/io/measurement_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

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

// What a detector states beyond the pose (extra noise, radius, box) is written in its columns,
// empty where a detection states none, and read back as it was.
TEST(MeasurementLogWriter, WritesWhatTheDetectionsStateAndReadsItBack) {
  Frame first{0.0, {}};
  first.detections.push_back({"cup", make_pose({0.5, 0.1, 0.03}, Eigen::Quaterniond::Identity()),
                              0.004, 0.045, Eigen::Vector3d::Zero()});
  first.detections.push_back({"hand", make_pose({0.6, 0.0, 0.2}, Eigen::Quaterniond::Identity()),
                              0.0, 0.0, Eigen::Vector3d(0.14, 0.14, 0.04)});
  Frame second{1.0 / 30.0, {}};
  second.detections.push_back({"cup", make_pose({0.52, 0.1, 0.03}, Eigen::Quaterniond::Identity()),
                               0.0, 0.045, Eigen::Vector3d::Zero()});
  const std::vector<Frame> frames = {first, second};
  const StatedColumns columns = stated_columns(frames);
  EXPECT_TRUE(columns.extra_noise && columns.radius && columns.box);
  std::ostringstream out;
  write_measurement_header(out, columns);
  write_measurement_rows(out, frames, columns);
  EXPECT_EQ(out.str().substr(0, out.str().find('\n')),
            "t,object,x,y,z,qx,qy,qz,qw,extra_noise,radius,box_x,box_y,box_z");
  EXPECT_NE(out.str().find("0,hand,0.6,0,0.2,0,0,0,1,,,0.14,0.14,0.04\n"), std::string::npos)
      << out.str();
  std::istringstream in(out.str());
  const MeasurementLog log = parse_measurement_log(in, "written.csv");
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[1].t, 1.0 / 30.0);
  for (std::size_t f = 0; f < 2; ++f) {
    ASSERT_EQ(log.frames[f].detections.size(), frames[f].detections.size());
    for (std::size_t i = 0; i < frames[f].detections.size(); ++i) {
      const Detection& read = log.frames[f].detections[i];
      const Detection& written = frames[f].detections[i];
      EXPECT_EQ(read.object, written.object);
      EXPECT_EQ(translation_of(read.pose), translation_of(written.pose));
      EXPECT_EQ(read.extra_noise, written.extra_noise);
      EXPECT_EQ(read.radius, written.radius);
      EXPECT_EQ(read.box, written.box);
    }
  }
  // Detections that state nothing: the nine columns alone.
  const std::vector<Frame> plain = {
      Frame{0.0, {{"ball", make_pose({0, 0, 0}, Eigen::Quaterniond::Identity())}}}};
  std::ostringstream bare;
  write_measurement_header(bare, stated_columns(plain));
  EXPECT_EQ(bare.str(), "t,object,x,y,z,qx,qy,qz,qw\n");
}

}  // namespace
}  // namespace opf
