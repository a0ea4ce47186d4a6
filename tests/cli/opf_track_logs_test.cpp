// `opf track` on logs shaped like real systems write them: piped in and out as a stream,
// answered frame by frame; other units and column names; gaps filled and marked; quiet runs.

#include "cli/opf_program.h"
#include "opf/io/estimate_csv.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace opf {
namespace {

const std::string kData = std::string(OPF_SOURCE_DIR) + "/experiments/data/";
const std::string kFast = " --particles 200 --threads 1";

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// A 30 Hz one-object log, t scaled by `time_scale`, with no rows for frames [gap_from, gap_to).
std::string ball_log(int frames, double time_scale = 1.0, int gap_from = -1, int gap_to = -1,
                     const std::string& header = "t,object,x,y,z,qx,qy,qz,qw") {
  std::ostringstream s;
  s.precision(12);
  s << header << "\n";
  for (int k = 0; k < frames; ++k) {
    if (k >= gap_from && k < gap_to) continue;
    s << k / 30.0 * time_scale << ",ball," << 0.1 + 0.01 * k << ",0.2,0.3,0,0,0,1\n";
  }
  return s.str();
}

std::size_t count_lines(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

TEST_F(OpfProgram, TrackPipedInAndOutWritesWhatABatchRunWrites) {
  const std::string log = kData + "example_log.csv";
  ASSERT_EQ(run("track --in " + log + " --out " + (dir_ / "batch.csv").string() + kFast), 0)
      << err();
  ASSERT_EQ(run("track --in - --out - " + kFast + " < " + log), 0) << err();
  EXPECT_EQ(out(), read(dir_ / "batch.csv"));
  // The summary goes to stderr when the estimates take stdout.
  EXPECT_TRUE(contains(err(), "estimates written to -")) << err();
}

TEST_F(OpfProgram, TrackAnswersAStreamBeforeItsInputEnds) {
  const auto est = dir_ / "est.csv";
  const std::string command =
      kOpf + " track --in - --out " + est.string() + kFast + " 2>" + (dir_ / "stderr").string();
  FILE* pipe = popen(command.c_str(), "w");
  ASSERT_NE(pipe, nullptr);
  const std::string log = ball_log(40);
  std::fputs(log.c_str(), pipe);
  std::fflush(pipe);
  // The input stays open: every frame but the last (whose end is not known yet) must be
  // answered already.
  std::size_t lines = 0;
  for (int i = 0; i < 400 && lines < 40; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    lines = count_lines(read(est));
  }
  EXPECT_EQ(lines, 40u);  // the header and frames 0..38
  EXPECT_EQ(pclose(pipe), 0) << err();
  EXPECT_EQ(count_lines(read(est)), 41u);
}

TEST_F(OpfProgram, TrackRefusesAnOutOfOrderStreamRowAtItsLine) {
  std::ofstream(dir_ / "log.csv") << ball_log(20) << "0.1,mug,0,0,0,0,0,0,1\n";
  EXPECT_EQ(run("track --in - --out - " + kFast + " < " + (dir_ / "log.csv").string()), 1);
  EXPECT_TRUE(contains(err(), "<stdin>:22: column 't': out of order")) << err();
  // Read whole, the same file is fine: a file may be unsorted.
  EXPECT_EQ(run("track --in " + (dir_ / "log.csv").string() + " --out - " + kFast), 0) << err();
}

TEST_F(OpfProgram, TrackRefusesTimesInMillisecondsUnlessTold) {
  const auto log = dir_ / "ms.csv";
  std::ofstream(log) << ball_log(30, 1000.0);
  const auto est = dir_ / "est.csv";
  EXPECT_EQ(run("track --in " + log.string() + " --out " + est.string() + kFast), 1);
  EXPECT_TRUE(contains(err(), log.string() + ":3: column 't'")) << err();
  EXPECT_TRUE(contains(err(), "--time-unit ms")) << err();
  EXPECT_FALSE(std::filesystem::exists(est));
  ASSERT_EQ(
      run("track --in " + log.string() + " --out " + est.string() + " --time-unit ms" + kFast), 0)
      << err();
  const auto records = read_estimate_csv(est);
  ASSERT_EQ(records.size(), 30u);
  EXPECT_NEAR(records.back().t, 29 / 30.0, 1e-9);
  EXPECT_EQ(run("track --in " + log.string() + " --out - --time-unit minutes"), 2);
  EXPECT_TRUE(contains(err(), "--time-unit': expected s, ms, us or ns")) << err();
}

TEST_F(OpfProgram, TrackFillsGapsAndSaysSoInTheModeColumn) {
  const auto log = dir_ / "gap.csv";
  std::ofstream(log) << ball_log(60, 1.0, 20, 35);  // no rows for 0.5 s
  const auto est = dir_ / "est.csv";
  ASSERT_EQ(run("track --in " + log.string() + " --out " + est.string() + kFast), 0) << err();
  EXPECT_TRUE(contains(err(), "15 frames filled inside 1 gap")) << err();
  const auto records = read_estimate_csv(est);
  ASSERT_EQ(records.size(), 60u);
  for (std::size_t k = 0; k < records.size(); ++k) {
    EXPECT_NEAR(records[k].t, static_cast<double>(k) / 30.0, 1e-9) << k;
    EXPECT_EQ(contains(records[k].mode, "+filled"), k >= 20 && k < 35) << records[k].mode;
  }
  ASSERT_EQ(
      run("track --in " + log.string() + " --out " + est.string() + " --no-fill --quiet" + kFast),
      0);
  EXPECT_EQ(read_estimate_csv(est).size(), 45u);
  EXPECT_EQ(err(), "");
  EXPECT_EQ(out(), "");
  // A rate at which each 33 ms interval would hold more than 10^5 frames: left unfilled, and the
  // warning says why (it said the gaps were longer than 10 s).
  ASSERT_EQ(run("track --in " + log.string() + " --out " + est.string() + " --rate 1e7" + kFast), 0)
      << err();
  EXPECT_EQ(read_estimate_csv(est).size(), 45u);
  EXPECT_TRUE(contains(err(),
                       "warning: 44 gaps left unfilled: longer than 10 s (a clock jump or a "
                       "pause) or than 100000 frames at 1e+07 Hz"))
      << err();
}

TEST_F(OpfProgram, TrackMapsTheLogsOwnColumnNames) {
  const auto log = dir_ / "named.csv";
  std::ofstream(log) << ball_log(30, 1.0, -1, -1, "time,name,x,y,z,rx,ry,rz,rw");
  EXPECT_EQ(run("track --in " + log.string() + " --out -" + kFast), 1);
  EXPECT_TRUE(contains(err(), "missing")) << err();
  ASSERT_EQ(run("track --in " + log.string() +
                " --out - --columns t=time,object=name,qx=rx,qy=ry,"
                "qz=rz,qw=rw" +
                kFast),
            0)
      << err();
  EXPECT_EQ(count_lines(out()), 31u);
  EXPECT_EQ(run("track --in " + log.string() + " --out - --columns speed=v"), 2);
  EXPECT_TRUE(contains(err(), "'speed' is not a column of the log format")) << err();
}

TEST_F(OpfProgram, ProgressIsDrawnOnATerminalOnly) {
  ASSERT_EQ(run("run " + std::string(OPF_SOURCE_DIR) +
                "/experiments/general_op.yaml --frames 3 --seeds 1 --estimators pf "
                "--particles 50 --no-figures --out " +
                (dir_ / "results").string()),
            0)
      << err();
  EXPECT_FALSE(contains(err(), "\033")) << err();
  EXPECT_FALSE(contains(err(), "\r")) << err();
}

}  // namespace
}  // namespace opf
