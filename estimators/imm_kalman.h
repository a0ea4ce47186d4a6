#pragma once
// The interacting-multiple-model Kalman filter baseline (Blom & Bar-Shalom 1988): per translation
// axis, three kinematic models on the common state (position, velocity, acceleration), constant
// position, constant velocity (cvkf's model) and constant acceleration, between which the object
// switches as a Markov chain; the orientation as cvkf's error-state filter. It predicts through
// gaps with the models' mixture.

#include "opf/core/estimator.h"
#include "opf/core/linear_kalman.h"
#include "opf/estimators/imm_options.h"
#include "opf/motion/tangent_rotation_filter.h"

#include <array>

namespace opf {

class ImmKalman final : public Estimator {
 public:
  /// The models, in the order of model_probabilities()' columns.
  enum Model { kConstantPosition = 0, kConstantVelocity = 1, kConstantAcceleration = 2 };
  static constexpr int kModels = 3;
  /// The models' short names, as Estimate::motion_model lists the most probable one per axis.
  static constexpr std::array<const char*, kModels> kModelNames = {"cp", "cv", "ca"};
  /// Model probabilities are kept at or above this (then renormalised), so a long gap or an
  /// outlier cannot rule a model out for good.
  static constexpr double kProbabilityFloor = 1e-12;

  /// Throws std::invalid_argument naming the first option that is not a positive finite number.
  explicit ImmKalman(const ImmOptions& options);

  std::string_view name() const override { return "imm"; }

  /// Position and orientation from the measurement with the observation covariance; the rates
  /// zero with the initial_*_std priors in every model; the models equally probable.
  Estimate initialise(double t, const mrpt::poses::CPose3D& first_measurement) override;

  /// Throws std::logic_error before initialise() and std::invalid_argument when `t` does not
  /// follow the previous time; the filter is unchanged in both cases.
  Estimate step(double t, const mrpt::poses::CPose3D* measurement,
                const EnsembleView& ensemble) override;

  /// The model probabilities, a row per axis (x, y, z), a column per Model; each row sums to 1.
  const Eigen::Matrix3d& model_probabilities() const { return probabilities_; }

  /// The combined (moment-matched) state (position, velocity, acceleration) of one axis and its
  /// covariance.
  const kalman::Vector<3>& combined_state(int axis) const { return combined_[axis].mean; }
  const kalman::Matrix<3>& combined_covariance(int axis) const {
    return combined_[axis].covariance;
  }

 private:
  struct Gaussian {
    kalman::Vector<3> mean = kalman::Vector<3>::Zero();
    kalman::Matrix<3> covariance = kalman::Matrix<3>::Identity();
  };
  using Bank = std::array<Gaussian, kModels>;  ///< one axis's model-matched filters

  /// `extra_noise` (m): the detector's stated extra noise of the position (observation_sigma).
  void predict_and_update(double dt, const Eigen::Vector3d* position, double extra_noise);
  void combine();
  Estimate make_estimate(EstimateMode mode) const;

  ImmOptions options_;
  bool initialised_ = false;
  double t_ = 0.0;

  std::array<Bank, 3> banks_;  ///< per axis x, y, z
  Eigen::Matrix3d probabilities_ = Eigen::Matrix3d::Constant(1.0 / kModels);
  std::array<Gaussian, 3> combined_;  ///< per axis
  TangentRotationFilter rotation_;    ///< constant angular velocity, as cvkf's
};

}  // namespace opf
