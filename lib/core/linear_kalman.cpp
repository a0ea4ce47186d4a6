#include "opf/core/linear_kalman.h"

namespace opf::kalman {

Matrix<6> white_noise_acceleration(double q, double dt) {
  const double q2 = q * q;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  Matrix<6> noise;
  noise.topLeftCorner<3, 3>() = q2 * dt * dt * dt / 3.0 * identity;
  noise.topRightCorner<3, 3>() = q2 * dt * dt / 2.0 * identity;
  noise.bottomLeftCorner<3, 3>() = q2 * dt * dt / 2.0 * identity;
  noise.bottomRightCorner<3, 3>() = q2 * dt * identity;
  return noise;
}

Matrix<6> constant_rate_transition(const Eigen::Matrix3d& value_block, double dt) {
  Matrix<6> f = Matrix<6>::Identity();
  f.topLeftCorner<3, 3>() = value_block;
  f.topRightCorner<3, 3>() = dt * Eigen::Matrix3d::Identity();
  return f;
}

LinearModel<3> constant_position_model(double q, double dt) {
  LinearModel<3> m{Matrix<3>::Zero(), Matrix<3>::Zero()};
  m.transition(0, 0) = 1.0;
  m.process_noise(0, 0) = q * q * dt;
  return m;
}

LinearModel<3> constant_velocity_model(double q, double dt) {
  LinearModel<3> m{Matrix<3>::Zero(), Matrix<3>::Zero()};
  m.transition.topLeftCorner<2, 2>() << 1.0, dt, 0.0, 1.0;
  const double q2 = q * q;
  m.process_noise.topLeftCorner<2, 2>() << q2 * dt * dt * dt / 3.0, q2 * dt * dt / 2.0,
      q2 * dt * dt / 2.0, q2 * dt;
  return m;
}

LinearModel<3> constant_acceleration_model(double q, double dt) {
  const double dt2 = dt * dt, dt3 = dt2 * dt;
  LinearModel<3> m;
  m.transition << 1.0, dt, dt2 / 2.0, 0.0, 1.0, dt, 0.0, 0.0, 1.0;
  m.process_noise << dt3 * dt2 / 20.0, dt2 * dt2 / 8.0, dt3 / 6.0,  //
      dt2 * dt2 / 8.0, dt3 / 3.0, dt2 / 2.0,                        //
      dt3 / 6.0, dt2 / 2.0, dt;
  m.process_noise *= q * q;
  return m;
}

}  // namespace opf::kalman
