// The dump of the effective settings (`opf config --dump`, the provenance of result files): every
// option the reader knows, with its value, in a form the reader takes back unchanged.

#include "opf/io/estimator_settings_yaml.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <set>
#include <string>

namespace opf {
namespace {

/// The key paths of every scalar or list in `node`: "pf.resampling.scheme", ...
void key_paths(const YAML::Node& node, const std::string& prefix, std::set<std::string>& out) {
  for (const auto& pair : node) {
    const std::string path = prefix + pair.first.Scalar();
    if (pair.second.IsMap())
      key_paths(pair.second, path + ".", out);
    else
      out.insert(path);
  }
}

TEST(EstimatorSettingsDump, ReadsBackToTheSameSettings) {
  EstimatorSettings s;
  s.pf.translation_particles = 123;
  s.pf.observation_noise_translation = 0.0123456789;
  s.pf.resampling.scheme = mrpt::bayes::CParticleFilter::prResidual;
  s.opf.occluder.camera_position = Eigen::Vector4d(0.5, -0.25, 1.5, 1.0);
  s.opf.occluder.plane = OccluderPlane::kLineOfSight;
  s.opf.dynamics.models = {MotionModel::kDampedVelocity, MotionModel::kConstantPosition};
  s.opf.dynamics.predictor = DynamicsPredictor::kPaper;
  s.oapf.spread_growth = 3.5;
  s.imm.mean_sojourn = 0.75;
  const std::string dumped = dump_estimator_settings(s);
  const EstimatorSettings back = parse_estimator_settings(dumped, "dump.yaml");
  // Byte-identical dumps: every value the dump holds came back.
  EXPECT_EQ(dump_estimator_settings(back), dumped);
  EXPECT_EQ(back.pf.translation_particles, 123u);
  EXPECT_EQ(back.pf.observation_noise_translation, 0.0123456789);
  EXPECT_EQ(back.pf.resampling.scheme, mrpt::bayes::CParticleFilter::prResidual);
  ASSERT_TRUE(back.opf.occluder.camera_position);
  EXPECT_EQ(*back.opf.occluder.camera_position, Eigen::Vector4d(0.5, -0.25, 1.5, 1.0));
  EXPECT_EQ(back.opf.dynamics.models, (std::vector<MotionModel>{MotionModel::kDampedVelocity,
                                                                MotionModel::kConstantPosition}));
  EXPECT_EQ(back.opf.dynamics.predictor, DynamicsPredictor::kPaper);
  EXPECT_EQ(back.oapf.spread_growth, 3.5);
  EXPECT_EQ(back.imm.mean_sojourn, 0.75);
  // Different settings dump differently.
  EXPECT_NE(dump_estimator_settings(EstimatorSettings{}), dumped);
}

TEST(EstimatorSettingsDump, HoldsEveryOptionOfTheShippedSettingsFile) {
  const YAML::Node shipped = YAML::LoadFile(
      (std::filesystem::path(OPF_SOURCE_DIR) / "experiments/configs/estimators.yaml").string());
  std::set<std::string> documented, dumped;
  key_paths(shipped, "", documented);
  key_paths(YAML::Load(dump_estimator_settings(EstimatorSettings{})), "", dumped);
  for (const std::string& key : documented) EXPECT_TRUE(dumped.count(key)) << key;
  // ... and documents every option: a key added to a description must be explained there.
  for (const std::string& key : dumped) EXPECT_TRUE(documented.count(key)) << key;
  // The defaults file and the dump of the defaults are the same settings.
  const EstimatorSettings from_file =
      parse_estimator_settings(YAML::Dump(shipped), "estimators.yaml");
  EXPECT_EQ(dump_estimator_settings(from_file), dump_estimator_settings(EstimatorSettings{}));
}

TEST(EstimatorSettingsDump, TheOpfHasAtMostThirtySettingsAndTheDynamicsSix) {
  // Few, stated knobs: a key added to `opf:` must replace one (or the limit be argued anew).
  EstimatorSettings s;
  s.opf.occluder.camera_position = Eigen::Vector4d(0.5, 0.0, 1.0, 1.0);  // the optional key too
  const YAML::Node opf = YAML::Load(dump_estimator_settings(s))["opf"];
  std::set<std::string> keys, dynamics;
  key_paths(opf, "", keys);
  key_paths(opf["dynamics"], "", dynamics);
  EXPECT_LE(keys.size(), 30u);
  EXPECT_GE(keys.size(), 20u);  // the walk found the section at all
  EXPECT_LE(dynamics.size(), 6u);
  EXPECT_TRUE(opf["occluder"]["camera_position"].IsSequence());
}

}  // namespace
}  // namespace opf
