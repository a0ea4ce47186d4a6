#include "opf/core/enum_names.h"
#include "opf/core/estimate_mode.h"
#include "opf/estimators/opf_options.h"
#include "opf/fit/trajectory_fit.h"
#include "opf/particles/particle_filter_options.h"
#include "opf/permanence/motion_classifier.h"
#include "opf/permanence/occluder_selection.h"
#include "opf/sim/experiment_config.h"
#include "opf/vision/object_segmenter.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

namespace {

using namespace opf;

// Every table: each word and each value once, and a word reads back to its value.
template <class Enum, std::size_t N>
void expect_one_to_one(const EnumNames<Enum, N>& table) {
  std::set<std::string_view> words;
  std::set<int> values;
  for (const auto& [value, name] : table) {
    EXPECT_FALSE(name.empty());
    EXPECT_TRUE(words.insert(name).second) << "twice: " << name;
    EXPECT_TRUE(values.insert(static_cast<int>(value)).second) << "twice: " << name;
    EXPECT_EQ(name_of(table, value), name);
    EXPECT_EQ(parse_name(table, name), value) << name;
  }
}

TEST(EnumNames, EveryTableIsOneToOne) {
  expect_one_to_one(kEstimateModeNames);
  expect_one_to_one(kResamplingSchemeNames);
  expect_one_to_one(kRobustLossNames);
  expect_one_to_one(kMotionTestNames);
  expect_one_to_one(kOccluderPlaneNames);
  expect_one_to_one(kRotationBankModelNames);
  expect_one_to_one(kBankModelNames);
  expect_one_to_one(kDynamicsPredictorNames);
  expect_one_to_one(sim::kShapeNames);
  expect_one_to_one(sim::kSensorKindNames);
  expect_one_to_one(vision::kSegmentationMethodNames);
}

TEST(EnumNames, TablesCoverTheirEnums) {
  // The last enumerator of each is in its table (the tables list the enums in order).
  EXPECT_EQ(name_of(kEstimateModeNames, EstimateMode::kRandomWalk), "random_walk");
  EXPECT_EQ(name_of(kOccluderPlaneNames, OccluderPlane::k3D), "3d");
  EXPECT_EQ(name_of(kBankModelNames, MotionModel::kBallistic), "ballistic");
  EXPECT_EQ(name_of(kRotationBankModelNames, RotationModel::kDampedAngularVelocity),
            "damped_angular_velocity");
  EXPECT_EQ(name_of(kResamplingSchemeNames, mrpt::bayes::CParticleFilter::prSystematic),
            "systematic");
  EXPECT_EQ(name_of(vision::kSegmentationMethodNames, vision::SegmentationMethod::kBackground),
            "background");
}

TEST(EnumNames, UnknownWordsAndValuesAreRefused) {
  EXPECT_EQ(parse_name(kRobustLossNames, "Huber"), std::nullopt);  // words are exact
  EXPECT_EQ(parse_name(kRobustLossNames, ""), std::nullopt);
  EXPECT_THROW(name_of(kRobustLossNames, static_cast<RobustLoss>(7)), std::invalid_argument);
}

TEST(EnumNames, ListsReadAsAnErrorMessageOffersThem) {
  EXPECT_EQ(name_list(kDynamicsPredictorNames), "bank or paper");
  EXPECT_EQ(name_list(kRobustLossNames), "squared, huber or cauchy");
  EXPECT_EQ(name_list(kResamplingSchemeNames), "multinomial, residual, stratified or systematic");
  constexpr EnumNames<RobustLoss, 1> one = {{{RobustLoss::kSquared, "squared"}}};
  EXPECT_EQ(name_list(one), "squared");
}

}  // namespace
