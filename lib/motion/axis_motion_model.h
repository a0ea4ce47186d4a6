#pragma once
// The common representation of the standard translation motion models, the ones the OPF's
// motion-model bank holds (permanence/motion_model_bank.h): one axis, the state x = (p, v)
// (position m, velocity m/s), and the linear-Gaussian step over dt,
//
//   x_k = F(dt) x_{k-1} + b(dt) + w,   w ~ N(0, Q(dt)),   z_k = H x_k + e,   H = [1 0],
//   e ~ N(0, R).
//
// Every model the bank holds fits this state: constant position pins v to 0 through F's second
// row (constant_position_motion.h), constant velocity (constant_velocity_motion.h), damped
// velocity (damped_velocity_motion.h) and ballistic motion (ballistic_motion.h). A model with its
// parameters is an AxisMotionModel, so the bank keeps its members in one array.

#include "opf/core/linear_kalman.h"

#include <span>
#include <string_view>
#include <vector>

namespace opf {

/// One step of a model over dt: F(dt), Q(dt) and the known input b(dt).
struct AxisMotionStep {
  kalman::Matrix<2> transition = kalman::Matrix<2>::Identity();
  kalman::Matrix<2> process_noise = kalman::Matrix<2>::Zero();
  kalman::Vector<2> offset = kalman::Vector<2>::Zero();
};

/// A step of the Kalman core's per-axis model over (p, v, a) (core/linear_kalman.h), restricted
/// to (p, v): the models they share, with b = 0.
AxisMotionStep position_velocity_block(const kalman::LinearModel<3>& model);

/// The four models, in the order a bank lists them.
enum class MotionModel { kConstantPosition, kConstantVelocity, kDampedVelocity, kBallistic };
inline constexpr int kMotionModelCount = 4;

/// "constant_position", "constant_velocity", "damped_velocity", "ballistic".
std::string_view model_name(MotionModel model);

/// A model with its parameters, on one axis.
struct AxisMotionModel {
  MotionModel model = MotionModel::kConstantVelocity;
  /// The white-noise density q: of the velocity (m/s/sqrt(Hz)) for constant position, of the
  /// acceleration (m/s^2/sqrt(Hz)) for the others.
  double intensity = 1.0;
  /// The velocity's time constant T (s), damped velocity only.
  double time_constant = 1.0;
  /// The known acceleration g along this axis (m/s^2), ballistic only.
  double acceleration = 0.0;

  /// F(dt), Q(dt), b(dt) of this model over dt >= 0 (s).
  AxisMotionStep step(double dt) const;
};

/// Each model's step over dt, in order (out is resized), as AxisMotionModel::step gives it, the
/// damped models at one time constant sharing their exponentials: a bank's members differ in q
/// and T, and with a camera's clock no two frames share a dt.
void steps_over(std::span<const AxisMotionModel> models, double dt,
                std::vector<AxisMotionStep>& out);

}  // namespace opf
