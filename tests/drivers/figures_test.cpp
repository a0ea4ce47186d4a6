#include "drivers/figures.h"

#include <mrpt/poses/CPose3D.h>
#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace opf::experiments {
namespace {

TEST(Figures, TitlesSayTheExperimentAndObjectOnce) {
  EXPECT_EQ(figure_title("baseball", "baseball", "translation error", 0),
            "baseball, translation error (seed 0)");
  EXPECT_EQ(figure_title("twin_mugs", "ball", "uncertainty trace(Q~)", 3),
            "twin_mugs: ball, uncertainty trace(Q~) (seed 3)");
}

/// A run of 30 frames, the ball hidden in frames 10-19: the OPF's trace grows while hidden, the
/// PF's and the CVKF's stay the same constant, as the baselines' do.
ExperimentResults synthetic_results() {
  ExperimentResults results;
  results.experiment = "roll";
  results.estimators = {"cvkf", "opf", "pf"};  // not in figure order
  results.seeds = 1;
  results.objects_of_interest = {"ball"};
  results.epsilon_safe = 0.1;
  for (const std::string& estimator : results.estimators)
    for (int k = 0; k < 30; ++k) {
      FrameRecord record;
      record.frame = k;
      record.estimator = estimator;
      record.visible = k < 10 || k >= 20;
      record.estimate.object = "ball";
      record.estimate.t = k / 30.0;
      record.estimate.pose.mean = mrpt::poses::CPose3D(0.01 * k, 0, 0, 0, 0, 0);
      const bool grows = estimator == "opf" && !record.visible;
      record.estimate.observation_trace = grows ? 0.0078 * std::pow(1.2, k - 9) : 0.0078;
      results.records.push_back(record);
    }
  return results;
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(Figures, EachChartIsWrittenAsPngAndSvgTheBaselinesNamedTogether) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("opf_figures_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  sim::ExperimentConfig config;
  config.name = "roll";
  config.objects_of_interest = {"ball"};
  const auto written = write_figures(dir, config, {}, synthetic_results());
  ASSERT_EQ(written.size(), 6u);  // three charts, no hypotheses, no snapshot (nothing rendered)
  for (const std::string name : {"translation_error", "rotation_error", "trace"})
    for (const std::string extension : {".png", ".svg"})
      EXPECT_TRUE(std::filesystem::exists(dir / ("roll_ball_" + name + extension))) << name;
  EXPECT_EQ(cv::imread((dir / "roll_ball_trace.png").string()).cols, 1800);
  const std::string trace = read(dir / "roll_ball_trace.svg");
  std::filesystem::remove_all(dir);
  // The legend in figure order, the two constant baselines as one entry; all three lines drawn.
  const std::size_t opf = trace.find(">opf</text>"), pf = trace.find(">pf = cvkf</text>");
  ASSERT_NE(opf, std::string::npos);
  ASSERT_NE(pf, std::string::npos);
  EXPECT_LT(opf, pf);
  EXPECT_NE(trace.find("data-label=\"cvkf\""), std::string::npos);
  EXPECT_NE(trace.find(">alert (0.1)</text>"), std::string::npos);
  EXPECT_NE(trace.find("roll: ball, uncertainty trace(Q"), std::string::npos);
}

}  // namespace
}  // namespace opf::experiments
