#pragma once
// Damped velocity: the velocity is an Ornstein-Uhlenbeck process that forgets itself with the
// time constant T (s) under white-noise acceleration of density q (m/s^2/sqrt(Hz)),
// dp = v dt, dv = -v / T dt + q dW (Singer 1970's model, there for the acceleration, here one
// order down). Its stationary velocity variance is
// q^2 T / 2. Exactly over dt, with x = dt / T and e = exp(-x), on the state (p, v):
//
//   F = [1  T (1 - e); 0  e],   b = 0,
//   Q = q^2 [T^3 (x - 2 (1 - e) + (1 - e^2) / 2)   T^2 (1 - e)^2 / 2;
//            T^2 (1 - e)^2 / 2                      T (1 - e^2) / 2].
//
// As T -> infinity it is constant velocity (F -> [1 dt; 0 1], Q -> q^2 [dt^3/3 dt^2/2; dt^2/2
// dt]); as T -> 0 the velocity is forgotten at once and the object stands still (F -> [1 0; 0 0],
// Q -> 0, the position random-walking with velocity density q T). The position variance is
// summed as its series in x for small x, where the closed form cancels.

#include "opf/motion/axis_motion_model.h"

namespace opf {

/// What the step over dt takes from T alone (its exponentials), shared by the members of a bank
/// that differ in q only.
struct DampedVelocityDecay {
  double time_constant = 1.0;     ///< T (s)
  double one_minus_e = 0.0;       ///< 1 - e, e = exp(-x), x = dt / T
  double one_minus_e2 = 0.0;      ///< 1 - e^2
  double e = 1.0;                 ///< e
  double position_bracket = 0.0;  ///< x - 2 (1 - e) + (1 - e^2) / 2
};
DampedVelocityDecay damped_velocity_decay(double time_constant, double dt);

/// F(dt), Q(dt) (b = 0) of damped velocity with acceleration density q (m/s^2/sqrt(Hz)), from
/// its decay over dt.
AxisMotionStep damped_velocity_motion(double q, const DampedVelocityDecay& decay);
/// The same with time constant T (s).
AxisMotionStep damped_velocity_motion(double q, double time_constant, double dt);

}  // namespace opf
