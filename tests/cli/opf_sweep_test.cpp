// End-to-end tests of `opf sweep`: a tiny grid (the first 40 frames of general_op at 200
// particles) run by the built binary.

#include "cli/csv_rows.h"
#include "cli/opf_program.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace opf {
namespace {

namespace fs = std::filesystem;

const std::string kGeneralOp = std::string(OPF_SOURCE_DIR) + "/experiments/general_op.yaml";

std::string tiny_sweep(const std::string& extra = "") {
  return "name: tiny\nexperiments: [general_op]\nestimators: [opf]\nseeds: 2\nparticles: 200\n"
         "parameters:\n  opf.uncertainty.kappa: [1.01, 1.1]\n" +
         extra;
}

class OpfSweep : public OpfProgram {
 protected:
  fs::path write_sweep(const std::string& text) {
    const fs::path path = dir_ / "tiny.yaml";
    std::ofstream(path) << text;
    return path;
  }
};

// The table has a row per run with its parameter; each row equals the same seed of a plain
// `opf run` with that setting; a second call runs nothing and a lost result is run again.
TEST_F(OpfSweep, RunsTheGridMatchesOpfRunAndResumes) {
  const fs::path sweep = write_sweep(tiny_sweep("frames: 40\n"));
  const fs::path results = dir_ / "out";
  ASSERT_EQ(run("sweep " + sweep.string() + " --out " + results.string() + " --jobs 2"), 0)
      << err();
  const std::string table = read(results / "tiny.csv");
  const auto rows = csv_rows(table);
  ASSERT_EQ(rows.size(), 4u) << table;
  for (const auto& row : rows) {
    EXPECT_EQ(row.at("status"), "ok");
    EXPECT_EQ(row.at("experiment"), "general_op");
    EXPECT_EQ(row.at("variant"), "default");
    EXPECT_EQ(row.at("frames"), "40");
  }
  EXPECT_EQ(rows[0].at("opf.uncertainty.kappa"), "1.01");
  EXPECT_EQ(rows[3].at("opf.uncertainty.kappa"), "1.1");
  EXPECT_EQ(rows[3].at("seed"), "1");
  EXPECT_NE(out().find("general_op  opf  default  1.1  ->"), std::string::npos) << out();
  // Beside the table, how it was made; each run's summary.json has its own settings.
  const std::string provenance = read(results / "tiny.provenance.json");
  EXPECT_NE(provenance.find("\"command\": \"opf sweep " + sweep.string()), std::string::npos)
      << provenance;
  EXPECT_NE(provenance.find("\"commit\": "), std::string::npos) << provenance;
  const std::string run_summary =
      read(results / "general_op/opf/default/opf.uncertainty.kappa=1.1/seed_1/summary.json");
  EXPECT_NE(run_summary.find("\"kappa\": 1.1"), std::string::npos) << run_summary;

  // The same seeds from one `opf run` with kappa 1.1.
  std::ofstream(dir_ / "kappa.yaml") << "opf:\n  uncertainty:\n    kappa: 1.1\n";
  ASSERT_EQ(run("run " + kGeneralOp + " --estimators opf --seeds 2 --particles 200 --frames 40" +
                " --no-figures --config " + (dir_ / "kappa.yaml").string() + " --out " +
                (dir_ / "ref").string()),
            0)
      << err();
  const auto reference = csv_rows(read(dir_ / "ref" / "general_op_runs.csv"));
  ASSERT_EQ(reference.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k)
    for (const char* metric : {"translation_error", "rotation_error_geodesic", "frames"})
      EXPECT_EQ(rows[2 + k].at(metric), reference[k].at(metric)) << metric << ", seed " << k;

  ASSERT_EQ(run("sweep " + sweep.string() + " --out " + results.string()), 0) << err();
  EXPECT_NE(out().find("4 of 4 runs in"), std::string::npos);
  EXPECT_NE(out().find("(4 were done before, 0 ran now)"), std::string::npos) << out();
  EXPECT_EQ(read(results / "tiny.csv"), table);

  fs::remove(results /
             "general_op/opf/default/opf.uncertainty.kappa=1.01/seed_1/general_op_runs.csv");
  ASSERT_EQ(run("sweep " + sweep.string() + " --out " + results.string()), 0) << err();
  EXPECT_NE(out().find("(3 were done before, 1 ran now)"), std::string::npos) << out();
  EXPECT_EQ(read(results / "tiny.csv"), table);
}

// Runs that fail are named with their logs, kept in the table as missing, and the exit status
// says so.
// The runs fail where the sweep file cannot tell: general_op's camera moved under the table,
// where it never sees the ball (a refusal of `opf run`).
TEST_F(OpfSweep, ReportsFailedRunsAndExitsNonZero) {
  std::ifstream shipped(std::string(OPF_SOURCE_DIR) + "/experiments/general_op.yaml");
  std::stringstream experiment;
  experiment << shipped.rdbuf();
  std::string text = experiment.str();
  text.replace(text.find("position: [0.55, 0.0, 0.49]"), 27, "position: [0.55, 0.0, -5.0]");
  std::ofstream(dir_ / "blind.yaml") << text;
  std::string spec = tiny_sweep("frames: 40\n");
  spec.replace(spec.find("[general_op]"), 12, "[blind.yaml]");
  const fs::path sweep = write_sweep(spec);
  const fs::path results = dir_ / "out";
  EXPECT_EQ(run("sweep " + sweep.string() + " --out " + results.string()), 1);
  EXPECT_NE(err().find("4 runs failed; their logs:"), std::string::npos) << err();
  const fs::path log = results / "blind/opf/default/opf.uncertainty.kappa=1.1/seed_0/log.txt";
  EXPECT_NE(err().find(log.string()), std::string::npos) << err();
  EXPECT_NE(read(log).find("in none of its 40 frames"), std::string::npos) << read(log);
  const auto rows = csv_rows(read(results / "tiny.csv"));
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& row : rows) {
    EXPECT_EQ(row.at("status"), "missing");
    EXPECT_EQ(row.at("translation_error"), "");
  }
  EXPECT_NE(out().find("0 of 4 runs in"), std::string::npos) << out();
}

// The Snakemake workflow runs the same sweep through `opf run` jobs and writes the same table.
TEST_F(OpfSweep, SnakemakeWorkflowWritesTheSameTable) {
  const fs::path sweep = write_sweep(tiny_sweep("frames: 40\n"));
  ASSERT_EQ(run("sweep " + sweep.string() + " --out " + (dir_ / "direct").string()), 0) << err();
  const std::string command = "snakemake -s " + std::string(OPF_SOURCE_DIR) +
                              "/workflow/Snakefile -d " + dir_.string() +
                              " --cores 2 --quiet --config sweep=" + sweep.string() +
                              " out=" + (dir_ / "workflow").string() + " opf=" + kOpf + " >" +
                              (dir_ / "snakemake.log").string() + " 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read(dir_ / "snakemake.log");
  EXPECT_EQ(read(dir_ / "workflow" / "tiny.csv"), read(dir_ / "direct" / "tiny.csv"));
  EXPECT_TRUE(fs::exists(dir_ / "workflow/general_op/opf/default/opf.uncertainty.kappa=1.1/"
                                "seed_1/settings.yaml"));
}

TEST_F(OpfSweep, ListsTheRunsWithoutRunningThem) {
  const fs::path sweep = write_sweep(tiny_sweep());
  ASSERT_EQ(run("sweep " + sweep.string() + " --list --out " + (dir_ / "out").string()), 0);
  EXPECT_NE(out().find("pending  general_op/opf/default/opf.uncertainty.kappa=1.01/seed_0\n"),
            std::string::npos)
      << out();
  EXPECT_NE(out().find("4 runs\n"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// --preset paper: every run starts from the paper's settings (the sweep's keys on top), and its
// runs are kept apart from the defaults'.
TEST_F(OpfSweep, APresetIsPassedToEveryRun) {
  const fs::path sweep = write_sweep(tiny_sweep());
  ASSERT_EQ(
      run("sweep " + sweep.string() + " --plan --preset paper --out " + (dir_ / "out").string()), 0)
      << err();
  EXPECT_NE(out().find(R"("--preset", "paper")"), std::string::npos) << out();
  ASSERT_EQ(run("sweep " + sweep.string() + " --plan"), 0) << err();
  EXPECT_EQ(out().find("--preset"), std::string::npos) << out();
  // Its default output directory is the sweep's name with the preset's.
  ASSERT_EQ(run("sweep " + sweep.string() + " --plan --preset paper"), 0) << err();
  EXPECT_NE(out().find("results/sweeps/tiny-paper"), std::string::npos) << out();
  EXPECT_EQ(run("sweep " + sweep.string() + " --list --preset literal"), 2);
  EXPECT_NE(err().find("expected default or paper, got \"literal\""), std::string::npos) << err();
}

// The sweep's provenance gives, per experiment, the settings its runs start from: the preset,
// under `paper` the experiment's own paper settings (the throw's order-2 fit), the sweep's config.
TEST_F(OpfSweep, ItsProvenanceGivesEachExperimentsStartingSettings) {
  std::ofstream(dir_ / "base.yaml") << "opf:\n  uncertainty:\n    kappa: 1.2\n";
  const fs::path sweep = write_sweep(
      "name: tiny\nexperiments: [general_op, baseball]\nestimators: [opf]\n"
      "config: " +
      (dir_ / "base.yaml").string() + "\n");
  const auto settings_under = [&](const std::string& preset) {
    const fs::path out = dir_ / preset;
    fs::create_directories(out);
    EXPECT_EQ(run("sweep " + sweep.string() + " --table-only --preset " + preset + " --out " +
                  out.string()),
              1)  // no run is done yet
        << err();
    return YAML::LoadFile((out / "tiny.provenance.json").string())["settings"];
  };
  // A table of runs from a directory where none has run is refused, naming it.
  EXPECT_EQ(run("sweep " + sweep.string() + " --table-only --out " + (dir_ / "none").string()), 2);
  EXPECT_NE(err().find("no sweep has run in " + (dir_ / "none").string()), std::string::npos)
      << err();
  const YAML::Node paper = settings_under("paper");
  EXPECT_EQ(paper["baseball"]["opf"]["trajectory"]["translation_order"].as<int>(), 2);
  EXPECT_EQ(paper["general_op"]["opf"]["trajectory"]["translation_order"].as<int>(), 1);
  EXPECT_EQ(paper["general_op"]["opf"]["dynamics"]["predictor"].as<std::string>(), "paper");
  const YAML::Node defaults = settings_under("default");
  for (const char* experiment : {"general_op", "baseball"}) {
    const YAML::Node opf = defaults[experiment]["opf"];
    EXPECT_EQ(opf["trajectory"]["translation_order"].as<int>(), 1) << experiment;
    EXPECT_EQ(opf["dynamics"]["predictor"].as<std::string>(), "bank") << experiment;
    EXPECT_DOUBLE_EQ(opf["uncertainty"]["kappa"].as<double>(), 1.2) << experiment;
    EXPECT_TRUE(opf["occluder"]["camera_position"].IsSequence()) << experiment;
  }
}

TEST_F(OpfSweep, RejectsABadSweepFileBeforeRunningAnything) {
  const fs::path sweep = write_sweep(tiny_sweep("sedes: 3\n"));
  EXPECT_EQ(run("sweep " + sweep.string() + " --out " + (dir_ / "out").string()), 1);
  EXPECT_NE(err().find(sweep.string() + ":8: key 'sedes': unknown key; did you mean 'seeds'?"),
            std::string::npos)
      << err();
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace
}  // namespace opf
