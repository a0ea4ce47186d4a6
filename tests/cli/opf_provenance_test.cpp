// A record of every run: `opf config --dump` prints the effective settings, and summary.json,
// sweep tables and `opf evaluate --out` carry the version, the commit, the command and the full
// settings they were made with.

#include "cli/opf_program.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace opf {
namespace {

const std::string kSource = OPF_SOURCE_DIR;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST_F(OpfProgram, ConfigDumpPrintsTheEffectiveSettingsAsASettingsFile) {
  ASSERT_EQ(run("config --dump --preset paper --particles 321"), 0) << err();
  const YAML::Node dump = YAML::Load(out());
  EXPECT_EQ(dump["pf"]["translation_particles"].as<int>(), 321);
  EXPECT_EQ(dump["opf"]["dynamics"]["predictor"].as<std::string>(), "paper");
  EXPECT_FALSE(dump["opf"]["velocity_drift"].as<bool>());
  EXPECT_FALSE(dump["opf"]["detector_noise"].as<bool>());
  // Taken back with --config, the same dump.
  const std::string first = out();
  std::ofstream(dir_ / "dumped.yaml") << first;
  ASSERT_EQ(run("config --dump --config " + (dir_ / "dumped.yaml").string()), 0) << err();
  EXPECT_EQ(out(), first);
  EXPECT_EQ(run("config"), 2);
  EXPECT_TRUE(contains(err(), "pass --dump")) << err();
}

TEST_F(OpfProgram, SummaryJsonRecordsTheVersionCommandAndEverySetting) {
  ASSERT_EQ(run("run " + kSource +
                "/experiments/general_op.yaml --frames 3 --seeds 1 --estimators pf "
                "--particles 50 --no-figures --out " +
                (dir_ / "results").string()),
            0)
      << err();
  const YAML::Node summary = YAML::LoadFile((dir_ / "results" / "summary.json").string());
  const YAML::Node provenance = summary["provenance"];
  ASSERT_TRUE(provenance.IsMap());
  EXPECT_FALSE(provenance["version"].as<std::string>().empty());
  EXPECT_FALSE(provenance["commit"].as<std::string>().empty());
  EXPECT_TRUE(contains(provenance["command"].as<std::string>(),
                       "opf run " + kSource + "/experiments/general_op.yaml --frames 3"));
  // The experiment's effective settings: its own file's values, the options, its camera.
  const YAML::Node settings = provenance["settings"]["general_op"];
  EXPECT_EQ(settings["pf"]["translation_particles"].as<int>(), 50);
  EXPECT_TRUE(settings["opf"]["occluder"]["camera_position"].IsSequence());
  EXPECT_TRUE(settings["oapf"]["spread_growth"].IsScalar());  // every option, not the changed
  EXPECT_TRUE(summary["experiments"]["general_op"]["pf"].IsMap());
}

// The baseball throw runs the default preset as every experiment does; under the paper preset its
// own settings (the order-2 fit, a wider random walk) come on the preset, and --config on both.
TEST_F(OpfProgram, AnExperimentsOwnSettingsApplyUnderThePaperPresetOnly) {
  const auto settings_of = [&](const std::string& options) {
    const std::filesystem::path out = dir_ / "baseball";
    EXPECT_EQ(
        run("run " + kSource + "/experiments/baseball.yaml --frames 3 --seeds 1 " +
            "--estimators pf --particles 50 --no-figures --out " + out.string() + " " + options),
        0)
        << err();
    return YAML::LoadFile((out / "summary.json").string())["provenance"]["settings"]["baseball"];
  };
  YAML::Node settings = settings_of("");
  EXPECT_EQ(settings["opf"]["trajectory"]["translation_order"].as<int>(), 1);
  EXPECT_EQ(settings["pf"]["process_noise"]["translation"].as<double>(), 0.05);
  EXPECT_EQ(settings["opf"]["dynamics"]["predictor"].as<std::string>(), "bank");

  settings = settings_of("--preset paper");
  EXPECT_EQ(settings["opf"]["trajectory"]["translation_order"].as<int>(), 2);
  EXPECT_EQ(settings["pf"]["process_noise"]["translation"].as<double>(), 0.2);
  EXPECT_EQ(settings["opf"]["dynamics"]["predictor"].as<std::string>(), "paper");
  EXPECT_EQ(settings["pf"]["reset_gate"].as<double>(), 0.0);  // the preset's own, kept

  std::ofstream(dir_ / "third_order.yaml") << "opf:\n  trajectory:\n    translation_order: 3\n";
  settings = settings_of("--preset paper --config " + (dir_ / "third_order.yaml").string());
  EXPECT_EQ(settings["opf"]["trajectory"]["translation_order"].as<int>(), 3);
  EXPECT_EQ(settings["pf"]["process_noise"]["translation"].as<double>(), 0.2);
}

TEST_F(OpfProgram, EvaluateWritesItsTablesAsCsvOrJson) {
  const std::string common = "evaluate --seeds 2 --particles 200 --estimators cvkf,pf --out ";
  ASSERT_EQ(run(common + (dir_ / "table.csv").string()), 0) << err();
  const std::string csv = read(dir_ / "table.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "estimator,translation,translation_std,rotation_paper,rotation_paper_std,"
            "rotation_geodesic,rotation_geodesic_std,hidden_translation,hidden_translation_std,"
            "hidden_rotation,hidden_rotation_std,visible_translation,visible_translation_std,"
            "visible_rotation,visible_rotation_std,coverage,coverage_std,error_over_sd,"
            "error_over_sd_std,nees_translation,nees_translation_std,nees_rotation,"
            "nees_rotation_std,inside95_translation,inside95_translation_std,inside95_rotation,"
            "inside95_rotation_std,reacquisition_error,reacquisition_error_std,"
            "reacquisition_frames,reacquisition_frames_std,alert_precision,alert_precision_std,"
            "alert_recall,alert_recall_std,nearest_hidden_translation,"
            "nearest_hidden_translation_std");
  EXPECT_TRUE(contains(csv, "\ncvkf,")) << csv;
  EXPECT_TRUE(contains(csv, "\npf,")) << csv;
  ASSERT_EQ(run(common + (dir_ / "table.json").string()), 0) << err();
  const YAML::Node json = YAML::LoadFile((dir_ / "table.json").string());
  EXPECT_EQ(json["estimators"]["cvkf"]["seeds"].as<int>(), 2);
  EXPECT_GT(json["estimators"]["pf"]["translation"]["mean"].as<double>(), 0.0);
  EXPECT_EQ(json["provenance"]["settings"]["pf"]["translation_particles"].as<int>(), 200);
  // The cvkf row of the file is the printed one.
  const double printed = std::stod(out().substr(out().find("\ncvkf") + 5));
  EXPECT_NEAR(json["estimators"]["cvkf"]["translation"]["mean"].as<double>(), printed, 5e-6);
  EXPECT_EQ(run(common + (dir_ / "table.txt").string()), 2);
  EXPECT_TRUE(contains(err(), ".csv or .json")) << err();
}

}  // namespace
}  // namespace opf
