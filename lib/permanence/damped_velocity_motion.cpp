#include "opf/permanence/damped_velocity_motion.h"

#include <cmath>

namespace opf {

AxisMotionStep damped_velocity_motion(double q, double time_constant, double dt) {
  const double t = time_constant;
  const double x = dt / t;
  const double one_minus_e = -std::expm1(-x);         // 1 - e
  const double one_minus_e2 = -std::expm1(-2.0 * x);  // 1 - e^2
  // x - 2 (1 - e) + (1 - e^2) / 2 = x^3 (1/3 - x/4 + 7 x^2/60 - x^3/24 + 31 x^4/2520 - ...):
  // the closed form loses about 3 eps / x^2 of its value to cancellation, the truncated series
  // about x^5 / 100; they meet near x = 0.01 at 1e-12.
  double position_bracket = 0.0;
  if (x < 0.01) {
    position_bracket =
        x * x * x *
        (1.0 / 3.0 + x * (-1.0 / 4.0 + x * (7.0 / 60.0 + x * (-1.0 / 24.0 + x * 31.0 / 2520.0))));
  } else {
    position_bracket = x - 2.0 * one_minus_e + one_minus_e2 / 2.0;
  }
  const double q2 = q * q;
  AxisMotionStep step;
  step.transition << 1.0, t * one_minus_e, 0.0, std::exp(-x);
  const double cross = q2 * t * t * one_minus_e * one_minus_e / 2.0;
  step.process_noise << q2 * t * t * t * position_bracket, cross, cross,
      q2 * t * one_minus_e2 / 2.0;
  return step;
}

}  // namespace opf
