// Estimates written as TUM trajectories read back as the same poses, one file per object.

#include "opf/io/estimate_tum.h"
#include "opf/io/measurement_log.h"

#include "opf/core/pose_conversion.h"

#include <gtest/gtest.h>

#include <sstream>

namespace opf {
namespace {

TEST(EstimateTum, WrittenEstimatesReadBackAsTheSamePoses) {
  std::ostringstream out;
  write_tum_header(out);
  Estimate e;
  e.object = "cup";
  e.t = 1403715273.268333;
  e.pose.mean =
      make_pose(Eigen::Vector3d(0.125, -0.29, 1.52),
                Eigen::Quaterniond(Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 2, 3).normalized())));
  write_tum_row(out, e);
  LogReadOptions options;
  options.format = LogFormat::kTum;
  options.object = "cup";
  std::istringstream in(out.str());
  const MeasurementLog log = parse_measurement_log(in, "est.tum", options);
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_DOUBLE_EQ(log.frames[0].t, e.t);
  const mrpt::poses::CPose3D& read = log.frames[0].detections[0].pose;
  EXPECT_NEAR((translation_of(read) - translation_of(e.pose.mean)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(orientation_of(read).angularDistance(orientation_of(e.pose.mean)), 0.0, 1e-9);
}

TEST(EstimateTum, OneFilePerObjectBesideTheNameGiven) {
  EXPECT_EQ(tum_paths("out/est.tum", {"cup"}), std::vector<std::filesystem::path>{"out/est.tum"});
  EXPECT_EQ(tum_paths("out/est.tum", {"cup", "a/b"}),
            (std::vector<std::filesystem::path>{"out/est_cup.tum", "out/est_a_b.tum"}));
}

}  // namespace
}  // namespace opf
