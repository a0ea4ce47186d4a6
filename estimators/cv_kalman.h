#pragma once
// The constant-velocity Kalman filter baseline: a linear KF on position + velocity and an
// error-state KF on orientation + body-frame angular velocity; it predicts through gaps.

#include "opf/core/estimator.h"
#include "opf/core/linear_kalman.h"
#include "opf/estimators/cv_kalman_options.h"
#include "opf/motion/tangent_rotation_filter.h"

namespace opf {

class ConstantVelocityKalman final : public Estimator {
 public:
  /// Throws std::invalid_argument naming the first option that is not a positive finite number.
  explicit ConstantVelocityKalman(const CvKalmanOptions& options);

  std::string_view name() const override { return "cvkf"; }

  /// Position and orientation from the measurement with the observation covariance; velocities
  /// zero with the initial_*_std priors.
  Estimate initialise(double t, const mrpt::poses::CPose3D& first_measurement) override;

  /// Throws std::logic_error before initialise() and std::invalid_argument when `t` does not
  /// follow the previous time; the filter is unchanged in both cases.
  Estimate step(double t, const mrpt::poses::CPose3D* measurement,
                const EnsembleView& ensemble) override;

 private:
  void predict(double dt);
  /// `extra_noise` (m): the detector's stated extra noise of the measurement (observation_sigma).
  void update(const mrpt::poses::CPose3D& measurement, double extra_noise);
  Estimate make_estimate(EstimateMode mode) const;

  CvKalmanOptions options_;
  bool initialised_ = false;
  double t_ = 0.0;

  kalman::Vector<6> translation_ = kalman::Vector<6>::Zero();  ///< (position, velocity)
  kalman::Matrix<6> translation_covariance_ = kalman::Matrix<6>::Identity();
  TangentRotationFilter rotation_;  ///< constant angular velocity
};

}  // namespace opf
