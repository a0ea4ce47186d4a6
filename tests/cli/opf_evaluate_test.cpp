// `opf evaluate`'s calibration, reacquisition, alert and time-hidden outputs, and `opf track
// --covariance`, on the bundled example log.

#include "opf_program.h"

#include "opf/io/csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace opf {
namespace {

std::vector<std::vector<std::string>> rows_of(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) rows.push_back(csv::split_line(line, "test", 1));
  return rows;
}

std::string cell(const std::vector<std::vector<std::string>>& rows, std::size_t row,
                 const std::string& column) {
  for (std::size_t i = 0; i < rows[0].size(); ++i)
    if (rows[0][i] == column) return rows.at(row).at(i);
  ADD_FAILURE() << "no column " << column;
  return "";
}

TEST_F(OpfProgram, EvaluateWritesCalibrationAndTheErrorAgainstTimeHidden) {
  const auto table = dir_ / "table.csv";
  const auto profile = dir_ / "profile.csv";
  ASSERT_EQ(run("evaluate --seeds 2 --particles 200 --estimators cvkf,pf --out " + table.string() +
                " --hidden-profile " + profile.string()),
            0)
      << err();
  EXPECT_NE(out().find("NEES/3 t"), std::string::npos) << out();
  // The first table says once, in its header, what its +- is.
  EXPECT_NE(out().find("\nerrors against the truth, each run's mean over frames (mean +- std over "
                       "2 seeds)\nestimator "),
            std::string::npos)
      << out();
  const auto rows = rows_of(read(table));
  ASSERT_EQ(rows.size(), 3u);
  for (std::size_t r = 1; r <= 2; ++r) {
    const double nees = std::stod(cell(rows, r, "nees_translation"));
    const double inside = std::stod(cell(rows, r, "inside95_translation"));
    EXPECT_TRUE(nees > 0.0 && std::isfinite(nees)) << cell(rows, r, "estimator");
    EXPECT_TRUE(inside >= 0.0 && inside <= 1.0);
    EXPECT_GE(std::stod(cell(rows, r, "reacquisition_frames")), 0.0);
  }
  const auto bins = rows_of(read(profile));
  ASSERT_EQ(bins[0], (std::vector<std::string>{"estimator", "time_hidden_from", "time_hidden_to",
                                               "frames", "hidden_translation", "hidden_rotation"}));
  ASSERT_GT(bins.size(), 3u);
  EXPECT_EQ(bins[1][0], "cvkf");
  EXPECT_EQ(bins[1][1], "0");
  EXPECT_EQ(bins[1][2], "0.1");
  EXPECT_GT(std::stoi(bins[1][3]), 0);
  // The Kalman filter's extrapolation error grows with time hidden on the example's motion.
  EXPECT_LT(std::stod(bins[1][4]), std::stod(bins[3][4]));
}

TEST_F(OpfProgram, EvaluateRefusesABadAlertDistanceOrProfileName) {
  EXPECT_EQ(run("evaluate --seeds 1 --estimators cvkf --alert-distance -1"), 2);
  EXPECT_NE(err().find("--alert-distance"), std::string::npos) << err();
  EXPECT_EQ(run("evaluate --seeds 1 --estimators cvkf --hidden-profile p.txt"), 2);
  EXPECT_NE(err().find("--hidden-profile"), std::string::npos) << err();
}

// A mistyped --seeds would run for years: a command makes at most 100 000 runs, seeds times the
// estimators (times the experiments), and the last seed's index fits in 64 bits.
TEST_F(OpfProgram, SeedsAreBoundedByTheRunsTheyMake) {
  EXPECT_EQ(run("evaluate --estimators cvkf,pf --seeds 50001"), 2);
  EXPECT_NE(err().find("'--seeds' must be at most 50000 here (2 runs a seed, at most 100000 runs "
                       "a command), got 50001"),
            std::string::npos)
      << err();
  EXPECT_EQ(run("evaluate --estimators cvkf --seeds 0"), 2);
  EXPECT_NE(err().find("'--seeds' must be at least 1"), std::string::npos) << err();
  const std::string experiment = std::string(OPF_SOURCE_DIR) + "/experiments/general_op.yaml";
  const std::string out = " --out " + (dir_ / "results").string();
  EXPECT_EQ(run("run " + experiment + out + " --estimators opf,pf,cvkf --seeds 33334"), 2);
  EXPECT_NE(err().find("'--seeds' must be at most 33333 here (3 runs a seed"), std::string::npos)
      << err();
  EXPECT_EQ(run("run " + experiment + out + " --seeds 2 --first-seed 18446744073709551614"), 2);
  EXPECT_NE(err().find("'--first-seed' must leave room for 2 seeds below 2^64"), std::string::npos)
      << err();
  EXPECT_FALSE(std::filesystem::exists(dir_ / "results"));
}

TEST_F(OpfProgram, EvaluateWarnsAsTrackDoesWhenTheOpfHasNoCamera) {
  // The example log has two objects: the OPF without a camera takes the line of sight as
  // straight down, and says so once; with a camera, or without the OPF, nothing is assumed.
  ASSERT_EQ(run("evaluate --seeds 1 --particles 100 --estimators opf,cvkf"), 0) << err();
  EXPECT_EQ(err(),
            "opf evaluate: warning: no camera position (--camera X,Y,Z, or X,Y,Z,0 for a camera "
            "infinitely far in that direction, or opf.occluder.camera_position): the occluder "
            "module takes the line of sight as straight down (-z); a log of `opf detect`, whose z "
            "is the depth, wants --camera 0,0,-1,0\n");
  ASSERT_EQ(run("evaluate --seeds 1 --particles 100 --estimators opf --camera 0.4,0,0.8"), 0)
      << err();
  EXPECT_EQ(err(), "");
  ASSERT_EQ(run("evaluate --seeds 1 --estimators cvkf"), 0) << err();
  EXPECT_EQ(err(), "");
}

TEST_F(OpfProgram, TrackWritesTheFullCovarianceOnRequest) {
  const auto est = dir_ / "est.csv";
  ASSERT_EQ(
      run("track --in " + std::string(OPF_SOURCE_DIR) +
          "/experiments/data/example_log.csv --estimator cvkf --covariance --out " + est.string()),
      0)
      << err();
  const auto rows = rows_of(read(est));
  ASSERT_GT(rows.size(), 10u);
  EXPECT_EQ(rows[0].size(), 21u + 21u);
  EXPECT_EQ(rows[0].back(), "cov_roll_roll");
  // The variance columns are the squares of the std columns.
  const double std_x = std::stod(cell(rows, 5, "std_x"));
  EXPECT_NEAR(std::stod(cell(rows, 5, "cov_x_x")), std_x * std_x, 1e-12 + 1e-9 * std_x * std_x);
}

}  // namespace
}  // namespace opf
