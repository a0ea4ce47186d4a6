#pragma once
// Constant position (a random walk): the position's velocity is white noise of density q
// (m/s/sqrt(Hz)), dp = q dW (Bar-Shalom, Li & Kirubarajan 2001, ch. 6, the first-order
// model). Over dt, on the bank's state (p, v) with v pinned to 0 by F:
//
//   F = [1 0; 0 0],   Q = [q^2 dt  0; 0  0],   b = 0.

#include "opf/motion/axis_motion_model.h"

namespace opf {

/// F(dt), Q(dt) (b = 0) of constant position with velocity density q (m/s/sqrt(Hz)).
AxisMotionStep constant_position_motion(double q, double dt);

}  // namespace opf
