#pragma once
// Constant velocity: white-noise acceleration of density q (m/s^2/sqrt(Hz)), dp = v dt,
// dv = q dW (Bar-Shalom, Li & Kirubarajan 2001, ch. 6, the continuous white-noise
// acceleration model). Exactly over dt, on the state (p, v):
//
//   F = [1 dt; 0 1],   Q = q^2 [dt^3/3  dt^2/2; dt^2/2  dt],   b = 0.

#include "opf/motion/axis_motion_model.h"

namespace opf {

/// F(dt), Q(dt) (b = 0) of constant velocity with acceleration density q (m/s^2/sqrt(Hz)).
AxisMotionStep constant_velocity_motion(double q, double dt);

}  // namespace opf
