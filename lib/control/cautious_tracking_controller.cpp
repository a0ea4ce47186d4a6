#include "opf/control/cautious_tracking_controller.h"

#include <cmath>
#include <stdexcept>

namespace opf {

void validate(const CautiousControllerOptions& options) {
  if (!(options.kp_nominal >= 0.0))
    throw std::invalid_argument("controller kp_nominal must be >= 0");
  if (!(options.kd_nominal >= 0.0 && options.kd_nominal <= 1.0))
    throw std::invalid_argument("controller kd_nominal must be in [0, 1]");
  if (!(options.epsilon_safe > 0.0))
    throw std::invalid_argument("controller epsilon_safe must be > 0");
  if (!(options.steepness >= 1.0))
    throw std::invalid_argument("controller steepness n must be >= 1");
}

double cautious_gain(double nominal, double uncertainty, const CautiousControllerOptions& options) {
  if (options.stop_at_epsilon_safe && uncertainty >= options.epsilon_safe) return 0.0;
  // (eps/2)^n / ((eps/2)^n + U^n) = 1 / (1 + (2U/eps)^n): no overflow for large n.
  const double ratio = 2.0 * std::max(uncertainty, 0.0) / options.epsilon_safe;
  return nominal / (1.0 + std::pow(ratio, options.steepness));
}

Eigen::Vector3d cautious_velocity_command(const Eigen::Vector3d& robot_position,
                                          const Eigen::Vector3d& object_position,
                                          const Eigen::Vector3d& object_velocity,
                                          double uncertainty,
                                          const CautiousControllerOptions& options) {
  const double kp = cautious_gain(options.kp_nominal, uncertainty, options);
  const double kd = cautious_gain(options.kd_nominal, uncertainty, options);
  return -kp * (robot_position - object_position) + kd * object_velocity;
}

}  // namespace opf
