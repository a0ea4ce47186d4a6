// End-to-end tests of `opf dropout` on the bundled example log.

#include "cli/opf_program.h"
#include "opf/io/csv.h"

#include <gtest/gtest.h>

#include <cmath>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace opf {
namespace {

const std::string kExample = std::string(OPF_SOURCE_DIR) + "/experiments/data/example_log.csv";

std::vector<std::vector<std::string>> rows_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::size_t line = 0;
  for (std::string text; std::getline(in, text);)
    rows.push_back(csv::split_line(text, path, ++line));
  return rows;
}

TEST_F(OpfProgram, DropoutRemovesExactlyTheRowsInTheWindows) {
  const std::string dropped = (dir_ / "dropped.csv").string();
  ASSERT_EQ(run("dropout --in " + kExample + " --out " + dropped +
                " --objects ball --length 0.3 --period 2 --start 0.5"),
            0)
      << err();
  const auto before = rows_of(kExample);
  const auto after = rows_of(dropped);
  ASSERT_EQ(after.size(), before.size());
  EXPECT_EQ(after[0], before[0]);  // the header, with its extra column
  // The example is 30 Hz for 6 s: t = k/30 printed with 6 decimals. The windows are
  // [0.5, 0.8), [2.5, 2.8), [4.5, 4.8): frames 15..23, 75..83, 135..143 (9 each).
  std::size_t blanked = 0;
  for (std::size_t i = 1; i < before.size(); ++i) {
    const double t = std::stod(before[i][0]);
    const long frame = std::lround(t * 30.0);
    const bool window = (frame >= 15 && frame <= 23) || (frame >= 75 && frame <= 83) ||
                        (frame >= 135 && frame <= 143);
    if (before[i][1] == "ball" && window) {
      for (std::size_t c = 2; c <= 8; ++c) EXPECT_EQ(after[i][c], "") << "line " << i + 1;
      EXPECT_EQ(after[i][0], before[i][0]);
      EXPECT_EQ(after[i][9], before[i][9]);  // the source column stays
      blanked += before[i][2].empty() ? 0 : 1;
    } else {
      EXPECT_EQ(after[i], before[i]) << "line " << i + 1;
    }
  }
  // 22 ball rows in the windows: 9 + 9 with a pose, and 4 without, in the ball's occlusion
  // [2, 3) (its even frames have a row with empty fields, its odd frames none).
  EXPECT_EQ(blanked, 18u);
  EXPECT_NE(out().find("removed 18 of " + std::to_string(before.size() - 1) + " rows"),
            std::string::npos)
      << out();

  // Deterministic: the same command writes the same bytes.
  const std::string again = (dir_ / "again.csv").string();
  ASSERT_EQ(run("dropout --in " + kExample + " --out " + again +
                " --objects ball --length 0.3 --period 2 --start 0.5"),
            0);
  EXPECT_EQ(read(again), read(dropped));
}

TEST_F(OpfProgram, DropoutOfEveryObjectByDefault) {
  const std::string dropped = (dir_ / "dropped.csv").string();
  ASSERT_EQ(run("dropout --in " + kExample + " --out " + dropped + " --length 0.5"), 0) << err();
  const auto before = rows_of(kExample);
  const auto after = rows_of(dropped);
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t i = 1; i < before.size(); ++i) {
    const long frame = std::lround(std::stod(before[i][0]) * 30.0);
    // Default windows [1, 1.5), [3, 3.5), [5, 5.5): frames 30..44, 90..104, 150..164.
    const bool window = (frame >= 30 && frame <= 44) || (frame >= 90 && frame <= 104) ||
                        (frame >= 150 && frame <= 164);
    EXPECT_EQ(after[i][2].empty(), window || before[i][2].empty()) << "line " << i + 1;
  }
}

TEST_F(OpfProgram, DropoutUsageErrors) {
  const std::string dropped = (dir_ / "dropped.csv").string();
  EXPECT_EQ(run("dropout --in " + kExample + " --out " + dropped), 2);
  EXPECT_NE(err().find("'--length' is required"), std::string::npos) << err();
  EXPECT_EQ(run("dropout --in " + kExample + " --out " + dropped + " --length 2 --period 2"), 2);
  EXPECT_NE(err().find("shorter than --period"), std::string::npos) << err();
  EXPECT_EQ(run("dropout --in " + kExample + " --out " + dropped + " --length abc"), 2);
  EXPECT_NE(err().find("'--length' expects a number, got 'abc'"), std::string::npos) << err();
  EXPECT_EQ(run("dropout --in " + kExample + " --out " + dropped + " --length 0.3 --objects cup"),
            1);
  EXPECT_NE(err().find("'cup'"), std::string::npos) << err();
  EXPECT_FALSE(std::filesystem::exists(dropped));  // nothing written on failure
  EXPECT_EQ(run("dropout --in " + (dir_ / "missing.csv").string() + " --out " + dropped +
                " --length 0.3"),
            1);
  EXPECT_NE(err().find("missing.csv"), std::string::npos) << err();
  EXPECT_EQ(run("dropout --help"), 0);
  EXPECT_NE(out().find("Usage: opf dropout"), std::string::npos);
}

}  // namespace
}  // namespace opf
