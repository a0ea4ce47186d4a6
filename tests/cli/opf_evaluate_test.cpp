// `opf evaluate`'s calibration, reacquisition, alert and time-hidden outputs, and `opf track
// --covariance`, on the bundled example log.

#include "opf_program.h"

#include "opf/io/csv.h"
#include "opf/io/unsized_log_note.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

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

// The bundled example's ball is hidden under the mug: the OPF keeps it left or carried, and
// evaluate says how near the nearest hypothesis came beside the main one's error. An estimator
// without hypotheses has its nearest error equal to its hidden error, and no line.
TEST_F(OpfProgram, EvaluateGivesTheNearestHypothesisBesideTheMainOne) {
  const auto table = dir_ / "table.csv";
  ASSERT_EQ(run("evaluate --seeds 2 --particles 300 --estimators opf,cvkf --camera 0,0,1,0 --out " +
                table.string()),
            0)
      << err();
  const std::string text = out();
  const std::string said = "\nopf        more than one hypothesis in ";
  const auto at = text.find(said);
  ASSERT_NE(at, std::string::npos) << text;
  EXPECT_EQ(text.find("cvkf       more than one hypothesis"), std::string::npos) << text;
  const auto rows = rows_of(read(table));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(cell(rows, 1, "estimator"), "opf");
  const double opf_nearest = std::stod(cell(rows, 1, "nearest_hidden_translation"));
  const double opf_main = std::stod(cell(rows, 1, "hidden_translation"));
  EXPECT_GT(opf_nearest, 0.0);
  EXPECT_LT(opf_nearest, opf_main);
  EXPECT_EQ(cell(rows, 2, "nearest_hidden_translation"), cell(rows, 2, "hidden_translation"));
}

TEST_F(OpfProgram, EvaluateRefusesABadAlertDistanceOrOutputName) {
  EXPECT_EQ(run("evaluate --seeds 1 --estimators cvkf --alert-distance -1"), 2);
  EXPECT_NE(err().find("--alert-distance"), std::string::npos) << err();
  EXPECT_EQ(run("evaluate --seeds 1 --estimators cvkf --hidden-profile p.txt"), 2);
  EXPECT_NE(err().find("--hidden-profile"), std::string::npos) << err();
  EXPECT_EQ(run("evaluate --seeds 1 --estimators cvkf --gap-errors g.txt"), 2);
  EXPECT_NE(err().find("--gap-errors"), std::string::npos) << err();
  const std::string same = (dir_ / "same.csv").string();
  EXPECT_EQ(run("evaluate --seeds 1 --estimators cvkf --out " + same + " --gap-errors " + same), 2);
  EXPECT_NE(err().find("--gap-errors"), std::string::npos) << err();
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
  // straight down, and says so once, first; with a camera, or without the OPF, nothing is assumed.
  const std::string warning =
      "opf evaluate: warning: no camera position (--camera X,Y,Z, or X,Y,Z,0 for a camera "
      "infinitely far in that direction, or opf.occluder.camera_position): the occluder "
      "module takes the line of sight as straight down (-z); a log of `opf detect`, whose z "
      "is the depth, wants --camera 0,0,-1,0\n";
  // The example log states no sizes: the note on that follows (the next test).
  const std::string note = "opf evaluate: note: " + unsized_log_note() + "\n";
  ASSERT_EQ(run("evaluate --seeds 1 --particles 100 --estimators opf,cvkf"), 0) << err();
  EXPECT_EQ(err(), warning + note);
  ASSERT_EQ(run("evaluate --seeds 1 --particles 100 --estimators opf --camera 0.4,0,0.8"), 0)
      << err();
  EXPECT_EQ(err(), note);
  ASSERT_EQ(run("evaluate --seeds 1 --estimators cvkf"), 0) << err();
  EXPECT_EQ(err(), "");
}

TEST_F(OpfProgram, EvaluateNotesAsTrackDoesThatTheOccluderModuleWorkedWithoutSizes) {
  // The example log states no sizes and the occluder module takes the ball under the mug: one
  // note after every run, not one a run; none for an estimator without the module, or where the
  // detections state a radius (12 cm: the mug still hides the ball).
  const std::string opening =
      "opf evaluate: note: the occluder module took a hidden object (carried or left) and no "
      "detection states a size (the radius or box_x,box_y,box_z columns)";
  const std::string evaluate = "evaluate --camera 0.4,0,0.8 --particles 500 --seeds 2 ";
  ASSERT_EQ(run(evaluate + "--estimators opf,cvkf"), 0) << err();
  EXPECT_EQ(err(), "opf evaluate: note: " + unsized_log_note() + "\n");
  EXPECT_EQ(err().find(opening), 0u) << err();
  ASSERT_EQ(run(evaluate + "--estimators cvkf"), 0) << err();
  EXPECT_EQ(err(), "");
  const std::string data = std::string(OPF_SOURCE_DIR) + "/experiments/data/";
  ASSERT_EQ(run(evaluate + "--estimators opf --in " +
                with_radius(data + "example_log.csv", "0.12").string() + " --truth " + data +
                "example_truth.csv"),
            0)
      << err();
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

// A cup moving at constant velocity and turning at a constant rate about a fixed axis, as a CSV
// row at t: what a truth at any rate says of it, exactly, when interpolated.
std::string cup_row(double t) {
  const Eigen::Vector3d p = Eigen::Vector3d(0.3, 0.2, 0.05) + Eigen::Vector3d(0.6, -0.3, 0.0) * t;
  const Eigen::Quaterniond q(Eigen::AngleAxisd(1.5 * t, Eigen::Vector3d::UnitZ()));
  std::ostringstream row;
  row.precision(17);
  row << t << ",cup," << p.x() << ',' << p.y() << ',' << p.z() << ',' << q.x() << ',' << q.y()
      << ',' << q.z() << ',' << q.w() << '\n';
  return row.str();
}

void write_cup(const std::filesystem::path& path, const std::vector<double>& times) {
  std::ofstream out(path);
  out << "t,object,x,y,z,qx,qy,qz,qw\n";
  for (double t : times) out << cup_row(t);
}

std::vector<double> times(int first, int last, double rate, double offset = 0.0) {
  std::vector<double> out;
  for (int k = first; k <= last; ++k) out.push_back(offset + k / rate);
  return out;
}

// A detector's log at 30 Hz with a 0.5 s gap, scored against motion capture at its own rate:
// the truth is taken at each estimate's time, so a 100 Hz truth whose rows fall between the
// log's frames and a 10 Hz one score every estimator as the truth at the log's own times does.
// Matched to the nearest row instead, the 100 Hz truth is 1 ms (0.7 mm) off every frame, and the
// 10 Hz one is refused.
TEST_F(OpfProgram, EvaluateTakesATruthAtItsOwnRateInterpolatedAtEachEstimate) {
  std::vector<double> log_times;
  for (double t : times(0, 89, 30.0))
    if (t < 1.3 || t > 1.8) log_times.push_back(t);
  write_cup(dir_ / "log.csv", log_times);
  write_cup(dir_ / "at_the_log.csv", times(0, 89, 30.0));
  write_cup(dir_ / "mocap_100hz.csv", times(-1, 300, 100.0, 0.001));
  write_cup(dir_ / "mocap_10hz.csv", times(-1, 30, 10.0, 0.05));
  const auto table = [&](const std::string& truth) {
    const auto written = dir_ / (truth + ".table.csv");
    EXPECT_EQ(run("evaluate --in " + (dir_ / "log.csv").string() + " --truth " +
                  (dir_ / (truth + ".csv")).string() +
                  " --estimators cvkf,opf --seeds 2 --particles 300 --out " + written.string()),
              0)
        << truth << ": " << err();
    EXPECT_EQ(out().find("not scored"), std::string::npos) << out();
    return rows_of(read(written));
  };
  const auto reference = table("at_the_log");
  ASSERT_EQ(reference.size(), 3u);
  for (std::size_t r = 1; r < reference.size(); ++r)  // the gap's frames are scored
    EXPECT_GT(std::stod(cell(reference, r, "hidden_translation")), 0.0);
  for (const std::string truth : {"mocap_100hz", "mocap_10hz"}) {
    const auto rows = table(truth);
    ASSERT_EQ(rows.size(), reference.size()) << truth;
    for (std::size_t r = 1; r < rows.size(); ++r)
      for (const char* column : {"translation", "hidden_translation", "visible_translation",
                                 "rotation_geodesic", "hidden_rotation", "nees_translation"})
        EXPECT_NEAR(std::stod(cell(rows, r, column)), std::stod(cell(reference, r, column)),
                    1e-9 * (1.0 + std::abs(std::stod(cell(reference, r, column)))))
            << truth << ", " << cell(rows, r, "estimator") << ", " << column;
  }
  // The gap's errors, pooled over the seeds: the log's one gap (1.3-1.8 s), 16 frames a seed,
  // whose mean is the table's hidden error.
  const auto gaps = dir_ / "gaps.csv";
  ASSERT_EQ(run("evaluate --in " + (dir_ / "log.csv").string() + " --truth " +
                (dir_ / "mocap_100hz.csv").string() +
                " --estimators cvkf,opf --seeds 2 --particles 300 --gap-errors " + gaps.string()),
            0)
      << err();
  const auto gap_rows = rows_of(read(gaps));
  ASSERT_EQ(gap_rows.size(), 3u) << read(gaps);
  EXPECT_EQ(gap_rows[0],
            (std::vector<std::string>{"estimator", "object", "gap_start", "gap_end", "frames",
                                      "hidden_translation", "hidden_rotation"}));
  for (std::size_t r = 1; r < gap_rows.size(); ++r) {
    EXPECT_EQ(cell(gap_rows, r, "estimator"), cell(reference, r, "estimator"));
    EXPECT_NEAR(std::stod(cell(gap_rows, r, "gap_start")), 1.3, 1e-6);
    EXPECT_NEAR(std::stod(cell(gap_rows, r, "gap_end")), 1.8, 1e-6);
    EXPECT_EQ(cell(gap_rows, r, "frames"), "32");
    EXPECT_NEAR(std::stod(cell(gap_rows, r, "hidden_translation")),
                std::stod(cell(reference, r, "hidden_translation")), 1e-9);
  }
  // A dropout of the truth is not bridged: a log frame inside it is refused, naming it.
  std::vector<double> with_dropout;
  for (double t : times(-1, 300, 100.0, 0.001))
    if (t < 0.5 || t > 0.8) with_dropout.push_back(t);
  write_cup(dir_ / "dropout.csv", with_dropout);
  EXPECT_EQ(run("evaluate --in " + (dir_ / "log.csv").string() + " --truth " +
                (dir_ / "dropout.csv").string() + " --estimators cvkf --seeds 1"),
            1);
  EXPECT_NE(err().find("no ground truth for object 'cup' at t = 0.5 (a dropout of the truth: no "
                       "rows from 0.491 to 0.801 s"),
            std::string::npos)
      << err();
}

}  // namespace
}  // namespace opf
