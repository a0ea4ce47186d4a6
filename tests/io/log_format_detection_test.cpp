// A TUM trajectory is told from a CSV log by its first line or its name.

#include "opf/io/log_format_detection.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

TEST(TumLog, IsDetectedByItsFirstLineOrName) {
  EXPECT_EQ(detect_log_format("a.csv", "# timestamp tx ty tz qx qy qz qw"), LogFormat::kTum);
  EXPECT_EQ(detect_log_format("a.tum", "1 2 3 4 5 6 7 8"), LogFormat::kTum);
  EXPECT_EQ(detect_log_format("a.txt", "1403715273.26 0.1 -0.2 1.5 0 0 0 1"), LogFormat::kTum);
  EXPECT_EQ(detect_log_format("a.txt", "1.0\t0.1\t-0.2\t1.5\t0\t0\t0\t1"), LogFormat::kTum);
  // Seven numbers, or a header, are not a TUM line; a .csv is CSV whatever its first line.
  EXPECT_EQ(detect_log_format("a.txt", "1 2 3 4 5 6 7"), LogFormat::kCsv);
  EXPECT_EQ(detect_log_format("a.txt", "t,object,x,y,z,qx,qy,qz,qw"), LogFormat::kCsv);
  EXPECT_EQ(detect_log_format("a.csv", "1 2 3 4 5 6 7 8"), LogFormat::kCsv);
  // Standard input, or what does not exist, cannot be looked at: CSV.
  EXPECT_EQ(detect_log_format("/nonexistent/a.tum"), LogFormat::kCsv);
}

}  // namespace
}  // namespace opf
