#pragma once
// Ballistic motion: constant velocity under a known acceleration g along the axis (gravity's
// component, g = -9.81 up[axis] m/s^2 for the unit vector `up`), with white-noise acceleration of
// density q (m/s^2/sqrt(Hz)) on top: dp = v dt, dv = g dt + q dW. The known input enters as b
// (Bar-Shalom, Li & Kirubarajan 2001, ch. 6: a known input u = g through G = [dt^2/2; dt]).
// Exactly over dt, on the state (p, v):
//
//   F = [1 dt; 0 1],   Q = q^2 [dt^3/3  dt^2/2; dt^2/2  dt],   b = (g dt^2/2, g dt).

#include "opf/motion/axis_motion_model.h"

namespace opf {

/// Standard gravity (m/s^2).
inline constexpr double kStandardGravity = 9.81;

/// F(dt), Q(dt), b(dt) of ballistic motion under the known acceleration g (m/s^2) with
/// acceleration density q (m/s^2/sqrt(Hz)).
AxisMotionStep ballistic_motion(double q, double g, double dt);

}  // namespace opf
