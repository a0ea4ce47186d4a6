#include "opf/io/estimate_csv.h"

#include "opf/core/pose_conversion.h"
#include "opf/io/csv.h"
#include "opf/io/input_error.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace opf {
namespace {

constexpr const char* kHeader =
    "t,object,x,y,z,qx,qy,qz,qw,trace,mode,std_x,std_y,std_z,std_yaw,std_pitch,std_roll,"
    "hypothesis,probability,alert,model\n";

// The feedback module's default threshold on trace(Q~).
constexpr double kEpsilonSafe = 0.1;

Estimate make_estimate(double t, const std::string& object, const mrpt::poses::CPose3D& mean) {
  mrpt::math::CMatrixDouble66 cov;
  cov.setZero();
  for (int i = 0; i < 6; ++i) cov(i, i) = 0.01 * (i + 1) * (i + 1);
  Estimate estimate;
  estimate.t = t;
  estimate.object = object;
  estimate.pose = mrpt::poses::CPose3DPDFGaussian(mean, cov);
  estimate.observation_trace = 3e-4;
  return estimate;
}

std::vector<std::string> split_row(const std::string& row) {
  return csv::split_line(row.substr(0, row.find('\n')), "row", 1);
}

class EstimateCsv : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("opf_estimate_csv_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::vector<Estimate>& estimates) {
    const auto path = dir_ / "estimates.csv";
    std::ofstream out(path, std::ios::binary);
    write_estimate_header(out);
    for (const auto& estimate : estimates) write_estimate_row(out, estimate, kEpsilonSafe);
    return path;
  }
  std::filesystem::path write_text(const std::string& text) {
    const auto path = dir_ / "edited.csv";
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  std::filesystem::path dir_;
};

TEST(EstimateCsvFormat, HeaderListsTheColumns) {
  std::ostringstream out;
  write_estimate_header(out);
  EXPECT_EQ(out.str(), kHeader);
}

TEST(EstimateCsvFormat, RowUsesShortestNumbersModeAndStandardDeviations) {
  Estimate estimate =
      make_estimate(0.033333, "ball", mrpt::poses::CPose3D(0.5, -0.25, 0.1, 0, 0, 0));
  estimate.mode = EstimateMode::kPredicted;
  std::ostringstream out;
  write_estimate_row(out, estimate, kEpsilonSafe);
  std::string expected = "0.033333,ball,0.5,-0.25,0.1,0,0,0,1,0.0003,predicted";
  expected.replace(expected.find("0.0003"), 6, csv::format_double(3e-4));
  for (int i = 0; i < 6; ++i)
    expected.append(",").append(csv::format_double(std::sqrt(estimate.pose.cov(i, i))));
  EXPECT_EQ(out.str(), expected + ",0,1,0,\n");
  EXPECT_EQ(split_row(out.str())[11], "0.1");  // sqrt(0.01)

  std::ostringstream third;
  estimate.t = 1.0 / 3.0;
  write_estimate_row(third, estimate, kEpsilonSafe);
  EXPECT_EQ(split_row(third.str())[0], "0.3333333333333333");

  // A whole-second epoch stamp keeps its digits, as the next frame's does.
  std::ostringstream stamped;
  estimate.t = 1600000000.0;
  write_estimate_row(stamped, estimate, kEpsilonSafe);
  EXPECT_EQ(split_row(stamped.str())[0], "1600000000");
}

TEST(EstimateCsvFormat, CovarianceColumnsAreTheUpperTriangleOnRequest) {
  std::ostringstream header;
  write_estimate_header(header, {.covariance = true});
  const auto names = split_row(header.str());
  ASSERT_EQ(names.size(), split_row(kHeader).size() + 21);
  EXPECT_EQ(names[split_row(kHeader).size()], "cov_x_x");
  EXPECT_EQ(names[split_row(kHeader).size() + 1], "cov_x_y");
  EXPECT_EQ(names[split_row(kHeader).size() + 6], "cov_y_y");
  EXPECT_EQ(names.back(), "cov_roll_roll");

  Estimate estimate = make_estimate(0.0, "cup", mrpt::poses::CPose3D(0, 0, 0, 0, 0, 0));
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) estimate.pose.cov(i, j) = (i == j ? 1.0 : 0.0) + 0.01 * (i + j);
  std::ostringstream row;
  write_estimate_row(row, estimate, kEpsilonSafe, {.covariance = true});
  const auto cells = split_row(row.str());
  ASSERT_EQ(cells.size(), names.size());
  std::size_t k = split_row(kHeader).size();
  for (int i = 0; i < 6; ++i)
    for (int j = i; j < 6; ++j, ++k)
      EXPECT_EQ(cells[k], csv::format_double(estimate.pose.cov(i, j)));
  // Without the request the row is the default one.
  std::ostringstream plain;
  write_estimate_row(plain, estimate, kEpsilonSafe);
  EXPECT_EQ(split_row(plain.str()).size(), split_row(kHeader).size());
}

TEST(EstimateCsvFormat, QuaternionHasNonNegativeW) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-3.14, 3.14);
  int flipped = 0;
  for (int i = 0; i < 200; ++i) {
    const mrpt::poses::CPose3D pose(0, 0, 0, angle(rng), angle(rng) / 2, angle(rng));
    if (orientation_of(pose).w() < 0) ++flipped;
    std::ostringstream out;
    write_estimate_row(out, make_estimate(0, "x", pose), kEpsilonSafe);
    const auto fields = split_row(out.str());
    const double qw = *csv::parse_double(fields[8]);
    EXPECT_GE(qw, 0.0);
    EXPECT_NE(fields[8][0], '-');
    const Eigen::Quaterniond written(qw, *csv::parse_double(fields[5]),
                                     *csv::parse_double(fields[6]), *csv::parse_double(fields[7]));
    EXPECT_LT(written.angularDistance(orientation_of(pose)), 1e-9);
  }
  // The check above only means something if some orientations needed the sign flip.
  EXPECT_GT(flipped, 0);
}

TEST_F(EstimateCsv, RoundTripsExactly) {
  std::vector<Estimate> estimates = {
      make_estimate(0.033333, "ball", mrpt::poses::CPose3D(0.1, 0.2, 0.3, 0.4, -0.5, 3.0)),
      make_estimate(1.0 / 30.0, "red, mug", mrpt::poses::CPose3D(-1e-7, 12345.678, 0, -3, 1.2, 0)),
      make_estimate(0.1 + 0.2, "ball", mrpt::poses::CPose3D(0, 0, 0, 0, 0, 0))};
  estimates[1].mode = EstimateMode::kPredicted;
  estimates[1].observation_trace = 1.0 / 7.0;
  estimates[2].mode = EstimateMode::kCarried;
  estimates[2].recovery = {.weights_underflow = true, .trace_capped = true};

  const auto records = read_estimate_csv(write(estimates));
  ASSERT_EQ(records.size(), estimates.size());
  for (std::size_t i = 0; i < records.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(records[i].t, estimates[i].t);
    EXPECT_EQ(records[i].object, estimates[i].object);
    EXPECT_EQ(translation_of(records[i].pose), translation_of(estimates[i].pose.mean));
    EXPECT_LT(
        orientation_of(records[i].pose).angularDistance(orientation_of(estimates[i].pose.mean)),
        1e-12);
    EXPECT_EQ(records[i].trace, estimates[i].observation_trace);
    EXPECT_EQ(records[i].mode, mode_column(estimates[i].mode, estimates[i].recovery));
  }
  EXPECT_EQ(records[2].mode, "carried+underflow+capped");
}

TEST_F(EstimateCsv, RoundTripsHypothesisAlertAndModel) {
  Estimate estimate = make_estimate(2.0, "ball", mrpt::poses::CPose3D(0.1, 0.2, 0.3, 0, 0, 0));
  estimate.hypothesis = 1;
  estimate.probability = 0.25;
  estimate.observation_trace = kEpsilonSafe;  // the alert is raised at epsilon_safe itself
  estimate.mode = EstimateMode::kDynamics;
  estimate.motion_model = "cv,cv,cp/cw";
  std::ostringstream out;
  write_estimate_row(out, estimate, kEpsilonSafe);
  const auto fields = split_row(out.str());
  ASSERT_EQ(fields.size(), 21u);
  EXPECT_EQ(fields[17], "1");
  EXPECT_EQ(fields[18], "0.25");
  EXPECT_EQ(fields[19], "1");
  // Quoted: the model holds commas.
  EXPECT_EQ(out.str().substr(out.str().size() - 15), ",\"cv,cv,cp/cw\"\n");
  const auto records = read_estimate_csv(write({estimate}));
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].hypothesis, 1);
  EXPECT_EQ(records[0].probability, 0.25);
  EXPECT_TRUE(records[0].alert);
  EXPECT_EQ(records[0].model, "cv,cv,cp/cw");
  // Any estimator's trace just under epsilon_safe raises none.
  estimate.observation_trace = std::nextafter(kEpsilonSafe, 0.0);
  std::ostringstream quiet;
  write_estimate_row(quiet, estimate, kEpsilonSafe);
  EXPECT_EQ(split_row(quiet.str())[19], "0");
}

TEST_F(EstimateCsv, WritingIsDeterministic) {
  const std::vector<Estimate> estimates = {
      make_estimate(0.5, "ball", mrpt::poses::CPose3D(0.1, 0.2, 0.3, 0.4, -0.5, 3.0))};
  std::ostringstream a, b;
  write_estimate_row(a, estimates[0], kEpsilonSafe);
  write_estimate_row(b, estimates[0], kEpsilonSafe);
  EXPECT_EQ(a.str(), b.str());
}

TEST_F(EstimateCsv, ReaderReportsBadFields) {
  const std::string header = kHeader;
  try {
    read_estimate_csv(write_text(header + "0,ball,1,2,3,0,0,0,1,0.1,measured,1,1,1,1,1,1,0,1,0,\n" +
                                 "0.1,ball,1,2,oops,0,0,0,1,0.1,measured,1,1,1,1,1,1,0,1,0,\n"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "z");
  }
  EXPECT_THROW(read_estimate_csv(write_text("t,object,x\n")), InputError);
  EXPECT_THROW(read_estimate_csv(
                   write_text(header + "0,ball,1,2,3,0,0,0,2,0.1,measured,1,1,1,1,1,1,0,1,0,\n")),
               InputError);
  EXPECT_THROW(read_estimate_csv(dir_ / "missing.csv"), InputError);
  try {  // a hypothesis's probability outside [0, 1]
    read_estimate_csv(
        write_text(header + "0,ball,1,2,3,0,0,0,1,0.1,measured,1,1,1,1,1,1,1,1.5,0,\n"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.field(), "probability");
  }
  // A hypothesis number past an int's range is refused before it is converted (the conversion
  // would be undefined), as are fractions and negatives.
  for (const char* hypothesis : {"1e300", "2147483648", "1.5", "-1"}) {
    try {
      read_estimate_csv(write_text(header + "0,ball,1,2,3,0,0,0,1,0.1,measured,1,1,1,1,1,1," +
                                   hypothesis + ",1,0,\n"));
      FAIL() << hypothesis;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "hypothesis") << hypothesis;
    }
  }
}

TEST_F(EstimateCsv, ReaderRejectsAModeItDoesNotKnowNamingLineAndColumn) {
  const std::string header = kHeader;
  const std::string good = "0,ball,1,2,3,0,0,0,1,0.1,measured+reset,1,1,1,1,1,1,0,1,0,\n";
  EXPECT_EQ(read_estimate_csv(write_text(header + good))[0].mode, "measured+reset");
  try {
    read_estimate_csv(write_text(header + good +
                                 "0.1,ball,1,2,3,0,0,0,1,0.1,measured+rest,1,1,1,1,1,1,0,1,0,\n"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "mode");
    EXPECT_NE(std::string(e.what()).find("'measured+rest'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace opf
