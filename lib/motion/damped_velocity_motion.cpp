#include "opf/motion/damped_velocity_motion.h"

#include <cmath>

namespace opf {

DampedVelocityDecay damped_velocity_decay(double time_constant, double dt) {
  DampedVelocityDecay d;
  d.time_constant = time_constant;
  const double x = dt / time_constant;
  d.one_minus_e = -std::expm1(-x);         // 1 - e
  d.one_minus_e2 = -std::expm1(-2.0 * x);  // 1 - e^2
  d.e = std::exp(-x);
  // x - 2 (1 - e) + (1 - e^2) / 2 = x^3 (1/3 - x/4 + 7 x^2/60 - x^3/24 + 31 x^4/2520 - ...):
  // the closed form loses about 3 eps / x^2 of its value to cancellation, the truncated series
  // about x^5 / 100; they meet near x = 0.01 at 1e-12.
  if (x < 0.01) {
    d.position_bracket =
        x * x * x *
        (1.0 / 3.0 + x * (-1.0 / 4.0 + x * (7.0 / 60.0 + x * (-1.0 / 24.0 + x * 31.0 / 2520.0))));
  } else {
    d.position_bracket = x - 2.0 * d.one_minus_e + d.one_minus_e2 / 2.0;
  }
  return d;
}

AxisMotionStep damped_velocity_motion(double q, const DampedVelocityDecay& decay) {
  const double t = decay.time_constant;
  const double q2 = q * q;
  AxisMotionStep step;
  step.transition << 1.0, t * decay.one_minus_e, 0.0, decay.e;
  const double cross = q2 * t * t * decay.one_minus_e * decay.one_minus_e / 2.0;
  step.process_noise << q2 * t * t * t * decay.position_bracket, cross, cross,
      q2 * t * decay.one_minus_e2 / 2.0;
  return step;
}

AxisMotionStep damped_velocity_motion(double q, double time_constant, double dt) {
  return damped_velocity_motion(q, damped_velocity_decay(time_constant, dt));
}

}  // namespace opf
