// KITTI tracking labels (and 3-D trackers' results in their format) as a log: each box the pose of
// its centre in the camera's frame with its extents, its track id the object, frame k at k / rate,
// DontCare regions skipped.

#include "io/scratch_directory.h"
#include "opf/core/pose_conversion.h"
#include "opf/io/input_error.h"
#include "opf/io/log_format_detection.h"
#include "opf/io/measurement_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace opf {
namespace {

namespace fs = std::filesystem;

// Label lines as in KITTI's label_02/0000.txt: frame, id, type, truncated, occluded, alpha, the 2-D
// box, height, width, length, the bottom centre x, y, z, rotation_y; the last with a score.
const std::string kLabels =
    "0 -1 DontCare -1 -1 -10.000000 219.31 188.49 245.50 218.56 -1000 -1000 -1000 -10 -1 -1 -1\n"
    "0 0 Van 0 0 -1.793451 296.74 161.75 455.22 292.37 2.000000 1.823255 4.433886 -4.552284 "
    "1.858523 13.410495 -2.115488\n"
    "0 2 Pedestrian 0 0 -2.523309 1106.13 166.57 1204.47 323.87 1.714062 0.767881 0.972283 "
    "6.301919 1.652419 8.455685 -1.900245\n"
    "1 0.0 Van 0 1 -1.796862 294.89 156.02 452.02 284.25 2.000000 1.823255 4.433886 -4.650955 "
    "1.766774 13.581085 -2.121565 0.93\n";

fs::path write(const std::string& name, const std::string& text) {
  const fs::path dir = scratch_directory("opf_kitti_tracking_log_test");
  std::ofstream(dir / name) << text;
  return dir / name;
}

LogReadOptions kitti(double rate) {
  LogReadOptions options;
  options.format = LogFormat::kKitti;
  options.rate = rate;
  options.fill_gaps = false;
  return options;
}

std::string error_of(const std::string& text) {
  try {
    read_measurement_log(write("bad.txt", text), kitti(10.0));
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(KittiTrackingLog, IsDetectedByALabelLine) {
  EXPECT_EQ(detect_log_format(write("0000.txt", kLabels)), LogFormat::kKitti);
  // A results line, with its score, too; the type must be a word, the rest numbers.
  EXPECT_EQ(detect_log_format("0001.txt", "0 4 Car 0 0 -1.5 1 2 3 4 1.5 1.6 3.9 1 1.7 20 -1.6 0.9"),
            LogFormat::kKitti);
  EXPECT_EQ(detect_log_format("0001.txt", "0 4 7 0 0 -1.5 1 2 3 4 1.5 1.6 3.9 1 1.7 20 -1.6"),
            LogFormat::kCsv);
  EXPECT_EQ(detect_log_format("0001.csv", "0 4 Car 0 0 -1.5 1 2 3 4 1.5 1.6 3.9 1 1.7 20 -1.6"),
            LogFormat::kCsv);
}

TEST(KittiTrackingLog, ReadsEachBoxAsItsCentreTurnedAboutYWithItsExtents) {
  const MeasurementLog log = read_measurement_log(write("0000.txt", kLabels), kitti(10.0));
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_DOUBLE_EQ(log.frames[1].t, 0.1);
  ASSERT_EQ(log.frames[0].detections.size(), 2u);  // the DontCare region is no object
  const Detection& van = log.frames[0].detections[0];
  EXPECT_EQ(van.object, "0");
  // y points down: the centre is half the 2 m height above the bottom centre's y.
  EXPECT_LT((translation_of(van.pose) - Eigen::Vector3d(-4.552284, 0.858523, 13.410495)).norm(),
            1e-12);
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(-2.115488, Eigen::Vector3d::UnitY()));
  EXPECT_LT(orientation_of(van.pose).angularDistance(turn), 1e-9);
  EXPECT_EQ(van.box, Eigen::Vector3d(4.433886, 2.0, 1.823255));  // length, height, width
  EXPECT_EQ(log.frames[0].detections[1].object, "2");
  EXPECT_EQ(log.frames[1].detections.at(0).object, "0");  // with a score, its id written 0.0
}

TEST(KittiTrackingLog, ErrorsNameTheLineAndField) {
  EXPECT_NE(error_of("0 0 Van 0 0 -1.79 296 161 455 292 2 1.8 4.4 -4.5 1.8 13.4\n")
                .find(":1: expected 17 to 18 fields separated by spaces (frame track_id type "),
            std::string::npos);
  EXPECT_NE(error_of("0.5 0 Van 0 0 -1.79 296 161 455 292 2 1.8 4.4 -4.5 1.8 13.4 -2.1\n")
                .find("column 'frame': expected a frame number (0, 1, ...), got \"0.5\""),
            std::string::npos);
  EXPECT_NE(error_of("0 0 Van 0 0 -1.79 296 161 455 292 0 1.8 4.4 -4.5 1.8 13.4 -2.1\n")
                .find("column 'height': expected an extent > 0 (m), got 0"),
            std::string::npos);
  EXPECT_NE(
      error_of("0 -2 Van 0 0 -1.79 296 161 455 292 2 1.8 4.4 -4.5 1.8 13.4 -2.1\n")
          .find(
              "column 'track_id': expected a track id, or -1 for DontCare (0, 1, ...), got \"-2\""),
      std::string::npos);
}

}  // namespace
}  // namespace opf
