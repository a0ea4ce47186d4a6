// End-to-end tests of `opf run --measurements`: a run's detections and truth written as logs,
// which `opf track` replays to the run's own estimates and `opf evaluate` scores.

#include "cli/csv_rows.h"
#include "cli/opf_program.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace opf {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = OPF_SOURCE_DIR;

// The word (up to a space or the line's end) that follows `label` in `text`; empty if none.
std::string word_after(const std::string& text, const std::string& label) {
  const std::size_t at = text.find(label);
  if (at == std::string::npos) return "";
  const std::size_t begin = at + label.size();
  return text.substr(begin, text.find_first_of(" \n", begin) - begin);
}

// general_op's first 30 frames, seed index 1 (so the replay's seed is not the first's), 200
// particles: the run writes the seed's detections and the truth, and prints the replay's seed.
TEST_F(OpfProgram, RunWritesTheDetectionsThatTrackReplaysToTheRunsEstimates) {
  const fs::path results = dir_ / "results";
  ASSERT_EQ(run("run " + (kSource / "experiments/general_op.yaml").string() +
                " --estimators opf --seeds 1 --first-seed 1 --frames 30 --particles 200 "
                "--no-figures --measurements --out " +
                results.string()),
            0)
      << err();
  const fs::path log = results / "general_op_measurements_seed1.csv";
  const fs::path truth = results / "general_op_truth.csv";
  ASSERT_TRUE(fs::exists(log)) << out();
  ASSERT_TRUE(fs::exists(truth)) << out();
  EXPECT_NE(out().find(", 2 measurement logs and their settings"), std::string::npos) << out();
  const std::string printed = out();
  const std::string seed = word_after(printed, "general_op_measurements_seed1.csv: --seed ");
  const std::string settings = word_after(printed, "opf track --in LOG --config ");
  ASSERT_FALSE(seed.empty()) << printed;
  EXPECT_EQ(fs::path(settings), results / "general_op_settings.yaml") << printed;
  // The detector states each detection's silhouette radius and, for a partial view, extra noise.
  const std::string log_text = read(log);
  EXPECT_EQ(log_text.substr(0, log_text.find('\n')),
            "t,object,x,y,z,qx,qy,qz,qw,extra_noise,radius,box_x,box_y,box_z");

  // Every row the run measured is in the log, and nothing else.
  const auto frames = csv_rows(read(results / "general_op_frames.csv"));
  std::size_t measured = 0;
  for (const auto& row : frames) measured += row.at("visible") == "1" ? 1 : 0;
  EXPECT_EQ(csv_rows(log_text).size(), measured);
  EXPECT_EQ(csv_rows(read(truth)).size(), 30u * 4u);  // ball, two mugs, box; 30 frames

  // Replayed with the printed settings (the run's particles and the experiment's camera among
  // them) and seed, opf track gives the run's estimates digit for digit.
  ASSERT_EQ(run("track --in " + log.string() + " --out " + (dir_ / "replay.csv").string() +
                " --estimator opf --config " + settings + " --seed " + seed),
            0)
      << err();
  std::map<std::pair<std::string, std::string>, std::map<std::string, std::string>> run_rows;
  for (const auto& row : frames)
    if (row.at("hypothesis") == "0") run_rows[{row.at("t"), row.at("object")}] = row;
  const auto replay = csv_rows(read(dir_ / "replay.csv"));
  ASSERT_EQ(replay.size(), run_rows.size());
  for (const auto& row : replay) {
    if (row.at("hypothesis") != "0") continue;
    const auto& expected = run_rows.at({row.at("t"), row.at("object")});
    for (const char* column : {"x", "y", "z", "qx", "qy", "qz", "qw", "trace", "mode"})
      EXPECT_EQ(row.at(column), expected.at(column))
          << column << " of " << row.at("object") << " at t = " << row.at("t");
  }

  // The truth log is what opf evaluate scores against.
  EXPECT_EQ(run("evaluate --in " + log.string() + " --truth " + truth.string() +
                " --estimators pf --seeds 1 --particles 200"),
            0)
      << err();
}

TEST_F(OpfProgram, RunRefusesMeasurementLogsOfAClosedLoop) {
  EXPECT_EQ(run("run " + (kSource / "experiments/sugar_drop.yaml").string() +
                " --measurements --seeds 1 --out " + (dir_ / "results").string()),
            2);
  EXPECT_NE(err().find("sugar_drop.yaml is a closed loop"), std::string::npos) << err();
  EXPECT_FALSE(fs::exists(dir_ / "results" / "sugar_drop_frames.csv"));
}

}  // namespace
}  // namespace opf
