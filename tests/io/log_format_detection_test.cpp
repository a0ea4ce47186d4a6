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
  // MOTChallenge: a .txt of seven or more comma-separated numbers (gt.txt, det.txt).
  EXPECT_EQ(detect_log_format("gt.txt", "1,7,100,200,40,80,1,1,0.9"), LogFormat::kMot);
  EXPECT_EQ(detect_log_format("det.txt", "1,-1,100,200,40,80,0.7,-1,-1,-1"), LogFormat::kMot);
  EXPECT_EQ(detect_log_format("a.txt", "1,2,3,4,5,6"), LogFormat::kCsv);
  EXPECT_EQ(detect_log_format("a.txt", "1,\"2,3,4,5,6,7"), LogFormat::kCsv);
  // Standard input, or what does not exist, cannot be looked at: CSV.
  EXPECT_EQ(detect_log_format("/nonexistent/a.tum"), LogFormat::kCsv);
}

}  // namespace
}  // namespace opf
