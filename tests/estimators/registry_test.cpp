#include "opf/estimators/registry.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

TEST(Registry, BuildsEveryRegisteredEstimatorUnderItsName) {
  const EstimatorSettings settings;
  ASSERT_EQ(estimator_names(), (std::vector<std::string>{"opf", "pf", "cvkf", "imm", "oapf"}));
  for (const auto& name : estimator_names()) {
    const auto estimator = make_estimator_factory(name, settings)("ball", 1);
    ASSERT_NE(estimator, nullptr);
    EXPECT_EQ(estimator->name(), name);
  }
}

TEST(Registry, UnknownNameListsTheKnownOnes) {
  try {
    make_estimator_factory("opff", EstimatorSettings{});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "unknown estimator 'opff' (known: opf, pf, cvkf, imm, oapf); did you mean 'opf'?");
  }
}

TEST(Registry, AFarMissSuggestsNothing) {
  EXPECT_EQ(unknown_estimator_message("ekf"),
            "unknown estimator 'ekf' (known: opf, pf, cvkf, imm, oapf)");
}

TEST(Registry, ValidatesOptionsWhenTheFactoryIsMade) {
  EstimatorSettings settings;
  settings.pf.observation_noise_translation = 0.0;
  EXPECT_THROW(make_estimator_factory("pf", settings), std::invalid_argument);
  settings = {};
  settings.cvkf.acceleration_noise = -1.0;
  EXPECT_THROW(make_estimator_factory("cvkf", settings), std::invalid_argument);
  settings = {};
  settings.imm.mean_sojourn = 0.0;
  EXPECT_THROW(make_estimator_factory("imm", settings), std::invalid_argument);
  settings = {};
  settings.oapf.miss_probability = 0.0;
  EXPECT_THROW(make_estimator_factory("oapf", settings), std::invalid_argument);
  settings = {};
  settings.opf.uncertainty.kappa = 1.0;
  EXPECT_THROW(make_estimator_factory("opf", settings), std::invalid_argument);
  // The shared particle options are validated for every particle estimator.
  settings = {};
  settings.pf.process_noise_rotation = -1.0;
  for (const char* name : {"opf", "oapf"})
    EXPECT_THROW(make_estimator_factory(name, settings), std::invalid_argument) << name;
}

}  // namespace
}  // namespace opf
