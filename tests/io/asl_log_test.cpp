// The ASL CSV (EuRoC's and TUM VI's ground truth and motion capture): read positionally, times in
// nanoseconds, the quaternion w first, further columns and '#' lines skipped; one object.

#include "io/scratch_directory.h"
#include "opf/core/pose_conversion.h"
#include "opf/io/input_error.h"
#include "opf/io/log_format_detection.h"
#include "opf/io/measurement_log.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace opf {
namespace {

namespace fs = std::filesystem;

// EuRoC MH_01's state_groundtruth_estimate0/data.csv, its header and first rows (velocities and
// biases after the pose).
const std::string kEurocGroundTruth =
    "#timestamp, p_RS_R_x [m], p_RS_R_y [m], p_RS_R_z [m], q_RS_w [], q_RS_x [], q_RS_y [], "
    "q_RS_z [], v_RS_R_x [m s^-1], v_RS_R_y [m s^-1], v_RS_R_z [m s^-1], b_w_RS_S_x [rad s^-1], "
    "b_w_RS_S_y [rad s^-1], b_w_RS_S_z [rad s^-1], b_a_RS_S_x [m s^-2], b_a_RS_S_y [m s^-2], "
    "b_a_RS_S_z [m s^-2]\n"
    "1403636580838555648,4.688319,-1.786938,0.783338,0.534108,-0.153029,-0.827383,-0.082152,"
    "-0.027876,0.033207,0.800006,-0.003172,0.021267,0.078502,-0.025266,0.136696,0.075593\n"
    "1403636580843555328,4.688177,-1.786770,0.787350,0.534640,-0.152990,-0.826976,-0.082863,"
    "-0.029272,0.033992,0.804594,-0.003172,0.021267,0.078502,-0.025266,0.136696,0.075593\n";

fs::path write(const std::string& name, const std::string& text) {
  const fs::path dir = scratch_directory("opf_asl_log_test");
  std::ofstream(dir / name) << text;
  return dir / name;
}

LogReadOptions asl(const std::string& object) {
  LogReadOptions options;
  options.format = LogFormat::kEuroc;
  options.object = object;
  options.fill_gaps = false;
  return options;
}

TEST(AslLog, IsDetectedByItsFirstRowAfterTheHeader) {
  const std::string header = "#timestamp [ns],p_RS_R_x [m],p_RS_R_y [m],p_RS_R_z [m],q_RS_w []";
  EXPECT_EQ(detect_log_format("data.csv", header,
                              "1403715333262142976,-0.25,-0.21,1.6,0.42,0.56,"
                              "-0.56,0.44"),
            LogFormat::kEuroc);
  // A '#' line over space-separated rows is TUM's; too few comma-separated numbers are not ASL.
  EXPECT_EQ(detect_log_format("g.txt", "# timestamp tx ty tz qx qy qz qw", "1 2 3 4 5 6 7 8"),
            LogFormat::kTum);
  EXPECT_EQ(detect_log_format("data.csv", header, "1,2,3,4,5,6,7"), LogFormat::kTum);
  EXPECT_EQ(detect_log_format(write("data.csv", kEurocGroundTruth)), LogFormat::kEuroc);
  // Blank lines and further '#' lines before the first row.
  EXPECT_EQ(detect_log_format(write("two_headers.csv", "\n# EuRoC\n" + kEurocGroundTruth)),
            LogFormat::kEuroc);
}

TEST(AslLog, ReadsNanosecondsAndTheQuaternionWFirst) {
  const MeasurementLog log = read_measurement_log(write("data.csv", kEurocGroundTruth), asl("mav"));
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_DOUBLE_EQ(log.frames[0].t, 1403636580.838555648);
  EXPECT_NEAR(log.frames[1].t - log.frames[0].t, 0.005, 1e-6);  // 200 Hz
  const Detection& first = log.frames[0].detections.at(0);
  EXPECT_EQ(first.object, "mav");
  EXPECT_EQ(translation_of(first.pose), Eigen::Vector3d(4.688319, -1.786938, 0.783338));
  const Eigen::Quaterniond expected =
      Eigen::Quaterniond(0.534108, -0.153029, -0.827383, -0.082152).normalized();
  EXPECT_LT(orientation_of(first.pose).angularDistance(expected), 1e-9);
  // --time-unit overrides the format's nanoseconds.
  LogReadOptions seconds = asl("mav");
  seconds.time_unit = TimeUnit::kSeconds;
  std::string in_seconds = kEurocGroundTruth;
  in_seconds.replace(in_seconds.find("1403636580838555648"), 19, "12.5");
  in_seconds.replace(in_seconds.find("1403636580843555328"), 19, "12.505");
  EXPECT_DOUBLE_EQ(read_measurement_log(write("s.csv", in_seconds), seconds).frames[1].t, 12.505);
}

TEST(AslLog, AShortRowIsRefusedAtItsLineWithTheFields) {
  const std::string text = kEurocGroundTruth + "1403636580848555520,4.688,-1.786,0.79\n";
  try {
    read_measurement_log(write("short.csv", text), asl("mav"));
    FAIL() << "accepted a row of four fields";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 4u);
    EXPECT_NE(std::string(e.what()).find("expected at least 8 fields separated by commas "
                                         "(timestamp, p_x, p_y, p_z, q_w, q_x, q_y, q_z), got 4"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace opf
