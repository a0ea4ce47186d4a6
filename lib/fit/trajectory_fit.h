#pragma once
// The dynamics module's trajectory model (paper Sec. III-B.1, Eq. 12, label eq:polyfit): fitted
// robustly once, at occlusion onset, to the last H estimates, then extrapolated every frame as
// virtual measurements.

#include "opf/core/enum_names.h"
#include "opf/core/option_schema.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <span>

namespace opf {

/// Highest polynomial order accepted for translation and rotation.
inline constexpr int kMaxTrajectoryOrder = 5;

struct TrajectorySample {
  double t = 0.0;  ///< s; strictly increasing along a fit's input
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

enum class RobustLoss { kSquared, kHuber, kCauchy };
inline constexpr EnumNames<RobustLoss, 3> kRobustLossNames = {{{RobustLoss::kSquared, "squared"},
                                                               {RobustLoss::kHuber, "huber"},
                                                               {RobustLoss::kCauchy, "cauchy"}}};

/// Options of fit_trajectory. The paper (Eq. 12) fits first-order polynomials with a squared loss;
/// the robust loss and the higher orders are this toolkit's extensions.
struct TrajectoryFitOptions {
  int translation_order = 1;  ///< per axis, in time; Eq. 12 uses 1, ballistic motion needs 2
  int rotation_order = 1;     ///< of the angle omega(t) about the fixed axis; Eq. 12 uses 1
  RobustLoss loss = RobustLoss::kHuber;  ///< robust to outlier detections
  double translation_loss_scale = 0.01;  ///< m: residual norm where the robust loss turns linear
  double rotation_loss_scale = 0.05;     ///< rad
  int max_iterations = 50;               ///< per solve (translation and rotation are separate)
};

/// The settings file's `opf.trajectory:` section (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, TrajectoryFitOptions& o) {
  constexpr Bounds order = between(0, kMaxTrajectoryOrder, "a polynomial order from 0 to 5");
  v.integer("translation_order", o.translation_order, order);
  v.integer("rotation_order", o.rotation_order, order);
  // The loss, its scales and the iterations are the fit's stated method (above), not settings.
}

/// What one Ceres solve did (the cost is Ceres': 1/2 sum of rho(|r_k|^2)).
struct FitSummary {
  double initial_cost = 0.0;
  double final_cost = 0.0;
  int iterations = 0;
  bool converged = false;  ///< a tolerance was reached, not the iteration limit
};

/// p(t) = sum_k c_k (t - t_ref)^k per axis and R(t) = R_ref exp(omega(t) e), with omega(t_ref) = 0
/// and e a unit axis in the body frame of R_ref. The default model rests at the origin.
class TrajectoryModel {
 public:
  Eigen::Vector3d position(double t) const;
  Eigen::Vector3d velocity(double t) const;  ///< dp/dt, m/s
  Eigen::Quaterniond orientation(double t) const;
  double angle(double t) const;         ///< omega(t), rad
  double angular_rate(double t) const;  ///< d omega / dt, rad/s; >= 0 at t_ref by convention
  const Eigen::Vector3d& axis() const { return axis_; }

  double reference_time() const { return t_ref_; }
  /// The fitted orientation at t_ref. It is the last sample corrected by the fit, not the last
  /// sample itself, so that noise on that one sample does not pin every extrapolation.
  const Eigen::Quaterniond& reference_orientation() const { return r_ref_; }
  int translation_order() const { return translation_order_; }
  int rotation_order() const { return rotation_order_; }
  /// c_k in m / s^k for k in [0, kMaxTrajectoryOrder]; zero beyond translation_order().
  Eigen::Vector3d translation_coefficient(int k) const { return translation_.col(k); }
  /// Coefficient of (t - t_ref)^k in omega(t), rad / s^k; k = 0 is always 0.
  double rotation_coefficient(int k) const { return omega_(k); }
  const FitSummary& translation_summary() const { return translation_summary_; }
  const FitSummary& rotation_summary() const { return rotation_summary_; }

 private:
  friend TrajectoryModel fit_trajectory(std::span<const TrajectorySample> samples,
                                        const TrajectoryFitOptions& options);

  double t_ref_ = 0.0;
  int translation_order_ = 0;
  int rotation_order_ = 0;
  Eigen::Matrix<double, 3, kMaxTrajectoryOrder + 1> translation_ =
      Eigen::Matrix<double, 3, kMaxTrajectoryOrder + 1>::Zero();
  Eigen::Quaterniond r_ref_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d axis_ = Eigen::Vector3d::UnitZ();
  Eigen::Matrix<double, kMaxTrajectoryOrder + 1, 1> omega_ =
      Eigen::Matrix<double, kMaxTrajectoryOrder + 1, 1>::Zero();
  FitSummary translation_summary_;
  FitSummary rotation_summary_;
};

/// Fits the model to `samples` (times relative to the last one, t_ref). Throws
/// std::invalid_argument for fewer samples than max(order) + 1, times not strictly increasing,
/// non-finite values, orders outside [0, kMaxTrajectoryOrder], non-positive loss scales or
/// iteration limit; std::runtime_error if Ceres returns no usable solution.
TrajectoryModel fit_trajectory(std::span<const TrajectorySample> samples,
                               const TrajectoryFitOptions& options);

}  // namespace opf
