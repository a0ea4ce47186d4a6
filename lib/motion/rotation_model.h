#pragma once
// The rotation models, one enum for the tangent-space filters (tangent_rotation_filter.h) of the
// Kalman baselines and of the OPF's rotation bank (permanence/rotation_model_bank.h):
// constant orientation (a random walk), constant angular velocity and damped angular velocity.

namespace opf {

enum class RotationModel { kConstantOrientation, kConstantAngularVelocity, kDampedAngularVelocity };

}  // namespace opf
