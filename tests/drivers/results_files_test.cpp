#include "drivers/results_files.h"
#include "io/scratch_directory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace opf::experiments {
namespace {

TEST(ResultsFiles, TheTableSaysOnceThatItIsTheMeanAndStdOverTheSeeds) {
  EXPECT_EQ(results_table_title("general_op", 5),
            "general_op: errors of the objects of interest, each run's mean over frames (mean +- "
            "std over 5 seeds)");
  EXPECT_TRUE(results_table_title("baseball", 1).ends_with("(1 seed: no spread)"));
}

// One seed has no spread: its table prints the means alone, never "+- 0.00e+00".
TEST(ResultsFiles, OneSeedPrintsTheMeansWithoutASpread) {
  ExperimentResults x;
  x.experiment = "throw";
  x.estimators = {"opf"};
  x.seeds = 1;
  RunErrors run;
  run.translation = 0.25;
  x.runs["opf"].push_back(run);
  std::ostringstream table;
  print_results_table(table, {x});
  const std::string text = table.str();
  EXPECT_NE(text.find("(1 seed: no spread)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  opf        0.25000   "), std::string::npos) << text;
  EXPECT_EQ(text.find("+-"), std::string::npos) << text;
}

TEST(ResultsFiles, TheTableAndSummaryGiveTheSampleStandardDeviation) {
  // Four seeds with translation errors 1, 2, 3, 4: mean 2.5, sample std sqrt(5/3).
  ExperimentResults x;
  x.experiment = "roll";
  x.estimators = {"opf"};
  x.seeds = 4;
  for (const double e : {1.0, 2.0, 3.0, 4.0}) {
    RunErrors run;
    run.translation = e;
    x.runs["opf"].push_back(run);
  }
  std::ostringstream table;
  print_results_table(table, {x});
  const std::string text = table.str();
  EXPECT_NE(text.find("\nroll: errors of the objects of interest, each run's mean over frames "
                      "(mean +- std over 4 seeds)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("  opf        2.50000 +- 1.29e+00 "), std::string::npos) << text;
  EXPECT_EQ(text.find("seeds"), text.rfind("seeds"));  // said once

  const auto path = scratch_directory("opf_results_files") / "summary.json";
  write_summary_json(path, {x});
  std::ifstream in(path);
  std::stringstream json;
  json << in.rdbuf();
  std::filesystem::remove(path);
  EXPECT_NE(json.str().find("\"translation_error\": {\"mean\": 2.5, \"std\": 1.2909944487358056}"),
            std::string::npos)
      << json.str();
}

}  // namespace
}  // namespace opf::experiments
