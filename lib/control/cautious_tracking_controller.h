#pragma once
// The cautious tracking controller of paper Sec. III-C.2, Eq. 16: the end-effector tracks the
// object's estimate with gains that fall from their nominal values towards zero as the filter's
// uncertainty U = trace(Q~) approaches the safety threshold.

#include <Eigen/Core>

namespace opf {

struct CautiousControllerOptions {
  double kp_nominal = 2.0;    ///< 1/s, k_p^nom (free in the paper)
  double kd_nominal = 1.0;    ///< k_d^nom in [0, 1], feedforward of the object's velocity
  double epsilon_safe = 0.1;  ///< the feedback module's threshold
  double steepness = 4.0;     ///< n >= 1 of the sigmoid
  /// At U >= epsilon_safe the paper's robot "should stop": gains are zero there. Without this the
  /// sigmoid alone leaves k_nom / (1 + 2^n) at U = epsilon_safe.
  bool stop_at_epsilon_safe = true;
};

/// k(U) = k_nom (eps/2)^n / ((eps/2)^n + U^n): k_nom at U = 0, k_nom/2 at U = eps/2.
double cautious_gain(double nominal, double uncertainty, const CautiousControllerOptions& options);

/// End-effector velocity command xi_r_dot = -k_p(U) (xi_r - xi_o) + k_d(U) xi_o_dot.
Eigen::Vector3d cautious_velocity_command(const Eigen::Vector3d& robot_position,
                                          const Eigen::Vector3d& object_position,
                                          const Eigen::Vector3d& object_velocity,
                                          double uncertainty,
                                          const CautiousControllerOptions& options);

/// Throws std::invalid_argument naming the first option out of range.
void validate(const CautiousControllerOptions& options);

}  // namespace opf
