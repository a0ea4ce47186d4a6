#include "opf/estimators/opf_options.h"

#include <algorithm>

namespace opf {
namespace {

template <class Enum>
bool holds(const std::vector<Enum>& models, Enum model) {
  return std::find(models.begin(), models.end(), model) != models.end();
}

}  // namespace

MotionModelBankOptions translation_bank_options(const DynamicsOptions& dynamics,
                                                double observation_noise) {
  MotionModelBankOptions bank;
  bank.constant_position = holds(dynamics.models, MotionModel::kConstantPosition);
  bank.constant_velocity = holds(dynamics.models, MotionModel::kConstantVelocity);
  bank.damped_velocity = holds(dynamics.models, MotionModel::kDampedVelocity);
  bank.ballistic = holds(dynamics.models, MotionModel::kBallistic);
  bank.memory = dynamics.memory;
  bank.observation_noise = observation_noise;
  bank.up = dynamics.up;
  return bank;
}

RotationModelBankOptions rotation_bank_options(const DynamicsOptions& dynamics,
                                               double observation_noise) {
  RotationModelBankOptions bank;
  bank.constant_orientation = holds(dynamics.rotation_models, RotationModel::kConstantOrientation);
  bank.constant_angular_velocity =
      holds(dynamics.rotation_models, RotationModel::kConstantAngularVelocity);
  bank.damped_angular_velocity =
      holds(dynamics.rotation_models, RotationModel::kDampedAngularVelocity);
  bank.memory = dynamics.memory;
  bank.observation_noise = observation_noise;
  return bank;
}

}  // namespace opf
