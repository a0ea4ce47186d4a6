#pragma once
// The rotation models, one enum for the rotation bank (rotation_model_bank.h) and the
// tangent-space filters of the Kalman baselines and the model bank (tangent_rotation_filter.h):
// constant orientation (a random walk), constant angular velocity and damped angular velocity.

namespace opf {

enum class RotationModel { kConstantOrientation, kConstantAngularVelocity, kDampedAngularVelocity };

}  // namespace opf
