#include "opf/permanence/motion_model_bank_options.h"

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace opf {
namespace {

std::string message_of(const MotionModelBankOptions& options) {
  try {
    validate(options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(MotionModelBankOptions, DefaultsAreValid) {
  EXPECT_EQ(message_of({}), "");
}

// Each bad value throws naming its option (and its unit).
TEST(MotionModelBankOptions, ABadOptionThrowsNamingIt) {
  struct Case {
    std::function<void(MotionModelBankOptions&)> spoil;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {[](auto& o) { o.memory = 0.0; }, "option memory must be a positive number (s)"},
      {[](auto& o) { o.memory = std::nan(""); }, "option memory must be"},
      {[](auto& o) { o.observation_noise = -0.01; },
       "option observation_noise must be a positive number (m)"},
      {[](auto& o) { o.up = Eigen::Vector3d::Zero(); }, "option up must be a non-zero vector"},
      {[](auto& o) { o.intensity_scale = 0.0; }, "option intensity_scale must be"},
      {[](auto& o) { o.initial_velocity_std = 0.0; },
       "option initial_velocity_std must be a positive number (m/s)"},
      {[](auto& o) {
         o.constant_position = o.constant_velocity = o.damped_velocity = o.ballistic = false;
       },
       "option models must include at least one model"},
  };
  for (const Case& c : cases) {
    MotionModelBankOptions options;
    c.spoil(options);
    const std::string message = message_of(options);
    EXPECT_NE(message.find("motion model bank " + c.expected), std::string::npos) << message;
  }
}

// One model alone is a bank.
TEST(MotionModelBankOptions, OneModelIsEnough) {
  MotionModelBankOptions options;
  options.constant_position = options.constant_velocity = options.damped_velocity = false;
  EXPECT_EQ(message_of(options), "");
}

}  // namespace
}  // namespace opf
