#pragma once
// One orientation model's error-state Kalman filter in the body tangent space: the state is the
// orientation R and its body-frame angular velocity w, the error (dtheta, dw) with R_true =
// R exp(dtheta) (core/so3.h), measured by H = [I 0] with isotropic variance (rad^2). Three models:
//
//   constant orientation       the orientation random-walks, white angular velocity of density
//                              q (rad/s/sqrt(Hz)): F = [I 0; 0 0], Q = [q^2 dt I 0; 0 0] (w
//                              pinned at 0);
//   constant angular velocity  R <- R exp(w dt), white angular acceleration q
//                              (rad/s^2/sqrt(Hz)): F = [exp(-w dt) dt I; 0 I] (the error carried
//                              through the step's own rotation, dw -> dtheta to first order),
//                              Q = q^2 [dt^3/3 I  dt^2/2 I; dt^2/2 I  dt I];
//   damped angular velocity    the rate an Ornstein-Uhlenbeck process of time constant T (s):
//                              dw = -w / T dt + q dW, so R <- R exp(w T (1 - e)), w <- e w,
//                              e = exp(-dt / T); F = [exp(-w T (1 - e))  T (1 - e) I; 0  e I],
//                              Q per axis damped_velocity_motion.h's.
//
// The rotation counterparts of constant position, constant velocity and damped velocity
// (Bar-Shalom, Li & Kirubarajan 2001, ch. 6; Singer 1970), per tangent axis: each axis steps by
// that model's (value, rate) F and Q, the value block turned by the step's own rotation.

#include "opf/core/linear_kalman.h"
#include "opf/motion/axis_motion_model.h"
#include "opf/motion/rotation_model.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string_view>

namespace opf {

/// "constant_orientation", "constant_angular_velocity".
std::string_view rotation_model_name(RotationModel model);

class TangentRotationFilter {
 public:
  /// `intensity` q: rad/s/sqrt(Hz) for constant orientation, rad/s^2/sqrt(Hz) for the rate
  /// models.
  /// `time_constant` T (s): damped angular velocity's (positive), ignored by the others. Throws
  /// std::invalid_argument for a damped model without a positive, finite T.
  TangentRotationFilter(RotationModel model, double intensity, double time_constant = 0.0);

  /// At `orientation` with std `orientation_std` (rad per tangent axis), the rate zero with std
  /// `rate_std` (rad/s; zero for constant orientation, whose rate is pinned).
  void initialise(const Eigen::Quaterniond& orientation, double orientation_std, double rate_std,
                  const Eigen::Vector3d& rate = Eigen::Vector3d::Zero());
  /// Steps the state over dt >= 0 (s).
  void predict(double dt);
  /// The same by `step`, axis_model()'s step over dt (steps_over: a bank computes its members'
  /// steps together).
  void predict(double dt, const AxisMotionStep& step);
  /// Updates with a measured orientation of tangent variance `variance` (rad^2 per axis), its
  /// noise Gaussian or, given `heavy_tails`, Student-t of that scale
  /// (kalman::update_covariance_student_t); returns the update's correction, with the
  /// innovation's squared distance and det S, and its log-likelihood under Gaussian noise (under
  /// Student-t noise left to the caller, as kalman::update_covariance_student_t leaves it). The
  /// quaternion's sign is irrelevant.
  kalman::Correction<6, 3> update(
      const Eigen::Quaterniond& measured, double variance,
      const std::optional<kalman::StudentTNoise>& heavy_tails = std::nullopt);

  /// The orientation `horizon` s ahead and its tangent covariance (rad^2) there.
  struct Prediction {
    Eigen::Quaterniond orientation;
    Eigen::Matrix3d covariance;
  };
  Prediction predicted(double horizon) const;
  /// The same by `step`, axis_model()'s step over the horizon.
  Prediction predicted(double horizon, const AxisMotionStep& step) const;
  /// How much the orientation's tangent covariance grows in trace over `horizon` s (rad^2):
  /// predicted(horizon).covariance.trace() less the present one's, in closed form.
  double orientation_variance_growth(double horizon) const;

  RotationModel model() const { return model_; }
  /// The model each tangent axis steps by: constant position, constant velocity or damped
  /// velocity, at this filter's q and T.
  AxisMotionModel axis_model() const;
  double intensity() const { return intensity_; }
  double time_constant() const { return time_constant_; }
  const Eigen::Quaterniond& orientation() const { return orientation_; }
  const Eigen::Vector3d& angular_velocity() const { return angular_velocity_; }
  /// Over the error state (dtheta, dw).
  const kalman::Matrix<6>& covariance() const { return covariance_; }

 private:
  bool has_rate() const { return model_ != RotationModel::kConstantOrientation; }
  /// axis_model()'s step over dt: the last predict's when dt is its interval.
  AxisMotionStep step_for(double dt) const;

  RotationModel model_;
  double intensity_;
  double time_constant_;
  /// The axis step of the last predict's dt, reused while frames keep one rate.
  double step_dt_ = -1.0;
  AxisMotionStep step_;
  Eigen::Quaterniond orientation_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d angular_velocity_ = Eigen::Vector3d::Zero();  ///< body frame
  kalman::Matrix<6> covariance_ = kalman::Matrix<6>::Identity();
};

}  // namespace opf
