#pragma once
// The rotation models, one enum for the dynamics module's predictor (motion_prediction.h) and the
// tangent-space filters of the Kalman baselines and the model bank (tangent_rotation_filter.h):
// constant orientation (a random walk) and constant angular velocity.

namespace opf {

enum class RotationModel { kConstantOrientation, kConstantAngularVelocity };

}  // namespace opf
