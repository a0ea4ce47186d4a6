#include "opf/core/linear_kalman.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <numbers>

namespace opf::kalman {
namespace {

// One constant-velocity axis, state (p, v), dt = 0.5, worked by hand:
//   F = [1 0.5; 0 1], Q = diag(0.1, 0.2), x = (1, 2), P = diag(1, 4)
//   predict: x = (2, 2), F P F^T = [2 2; 2 4], P = [2.1 2; 2 4.2]
//   update with H = [1 0], R = 0.9, z = 3.5: r = 1.5, S = 3, K = (0.7, 2/3),
//   x = (3.05, 3), P = P - K H P = [0.63 0.6; 0.6 4.2 - 4/3],
//   log N(1.5; 0, 3) = -(1.5^2 / 3 + log 3 + log 2 pi) / 2.
TEST(LinearKalman, PredictAndUpdateMatchHandComputedNumbers) {
  Vector<2> x(1.0, 2.0);
  Matrix<2> p = Vector<2>(1.0, 4.0).asDiagonal();
  Matrix<2> f;
  f << 1.0, 0.5, 0.0, 1.0;
  const Matrix<2> q = Vector<2>(0.1, 0.2).asDiagonal();
  predict(x, p, f, q);
  EXPECT_DOUBLE_EQ(x[0], 2.0);
  EXPECT_DOUBLE_EQ(x[1], 2.0);
  EXPECT_DOUBLE_EQ(p(0, 0), 2.1);
  EXPECT_DOUBLE_EQ(p(0, 1), 2.0);
  EXPECT_DOUBLE_EQ(p(1, 0), 2.0);
  EXPECT_DOUBLE_EQ(p(1, 1), 4.2);

  const Matrix<1, 2> h(1.0, 0.0);
  const Matrix<1> r = Matrix<1>::Constant(0.9);
  const Correction<2, 1> c = update<2, 1>(x, p, h, r, Vector<1>(3.5));
  EXPECT_DOUBLE_EQ(c.innovation[0], 1.5);
  EXPECT_DOUBLE_EQ(c.correction[0], 1.05);
  EXPECT_DOUBLE_EQ(c.correction[1], 1.0);
  EXPECT_DOUBLE_EQ(x[0], 3.05);
  EXPECT_DOUBLE_EQ(x[1], 3.0);
  EXPECT_NEAR(p(0, 0), 0.63, 1e-15);
  EXPECT_NEAR(p(0, 1), 0.6, 1e-15);
  EXPECT_NEAR(p(1, 0), 0.6, 1e-15);
  EXPECT_NEAR(p(1, 1), 4.2 - 4.0 / 3.0, 1e-15);
  EXPECT_DOUBLE_EQ(c.log_likelihood,
                   -0.5 * (1.5 * 1.5 / 3.0 + std::log(3.0) + std::log(2.0 * std::numbers::pi)));
}

TEST(LinearKalman, LogLikelihoodIsTheInnovationsGaussianDensity) {
  // A 3-state filter observed in two correlated components: log N(r; 0, S) from the determinant
  // and the inverse of S = H P H^T + R directly.
  Matrix<3> p;
  p << 2.0, 0.3, -0.2, 0.3, 1.5, 0.4, -0.2, 0.4, 0.8;
  Matrix<2, 3> h;
  h << 1.0, 0.5, 0.0, 0.0, -1.0, 2.0;
  Matrix<2> r;
  r << 0.5, 0.1, 0.1, 0.3;
  const Vector<3> x(0.2, -0.4, 1.0);
  const Vector<2> z(1.1, 0.7);
  const Matrix<2> s = h * p * h.transpose() + r;
  const Vector<2> innovation = z - h * x;
  const double expected = -0.5 * innovation.dot(s.inverse() * innovation) -
                          0.5 * std::log((2.0 * std::numbers::pi * s).determinant());

  Vector<3> mean = x;
  Matrix<3> covariance = p;
  const Correction<3, 2> c = update<3, 2>(mean, covariance, h, r, z);
  EXPECT_NEAR(c.log_likelihood, expected, 1e-12);
  EXPECT_TRUE(c.innovation.isApprox(innovation, 1e-15));

  // The posterior is the textbook one, symmetric exactly, and smaller than the prior.
  const Matrix<3, 2> gain = p * h.transpose() * s.inverse();
  EXPECT_TRUE(mean.isApprox(x + gain * innovation, 1e-12));
  EXPECT_TRUE(covariance.isApprox((Matrix<3>::Identity() - gain * h) * p, 1e-12));
  EXPECT_EQ(covariance, covariance.transpose());
  EXPECT_LT(covariance.trace(), p.trace());

  // update_covariance() leaves the mean to the caller and returns the same correction.
  Matrix<3> covariance2 = p;
  const Correction<3, 2> c2 = update_covariance<3, 2>(covariance2, h, r, innovation);
  EXPECT_EQ(c2.correction, c.correction);
  EXPECT_EQ(covariance2, covariance);
  EXPECT_EQ(c2.log_likelihood, c.log_likelihood);
}

// The hand-computed case above under Student-t noise: S = 3, r = 1.5, d^2 = 0.75, one degree of
// freedom, M = 1: R scaled by (1 + 0.75) / 2 = 0.875, so S' = 2.1 + 0.7875, K = 2.1 / 2.8875.
TEST(LinearKalman, StudentTUpdateScalesTheNoiseByTheInnovationsDistance) {
  const Matrix<1, 2> h(1.0, 0.0);
  const Matrix<1> r = Matrix<1>::Constant(0.9);
  Matrix<2> p;
  p << 2.1, 2.0, 2.0, 4.2;
  Matrix<2> expected_p = p;
  const Correction<2, 1> gaussian =
      update_covariance<2, 1>(expected_p, h, Matrix<1>::Constant(0.9 * 0.875), Vector<1>(1.5));
  const Correction<2, 1> c =
      update_covariance_student_t<2, 1>(p, h, r, Vector<1>(1.5), student_t_noise<1>(1.0));
  EXPECT_NEAR(c.correction[0], 1.5 * 2.1 / 2.8875, 1e-15);
  EXPECT_EQ(c.correction, gaussian.correction);
  EXPECT_EQ(p, expected_p);
  // d^2 under the unscaled S = 2.1 + 0.9: what a gate tests.
  EXPECT_NEAR(c.squared_distance, 1.5 * 1.5 / 3.0, 1e-15);
  // The Cauchy density of 1.5 with scale sqrt(3): 1 / (pi sqrt(3) (1 + 0.75)), from d^2 and
  // det S, which the update leaves to its caller.
  EXPECT_EQ(c.determinant, 3.0);
  EXPECT_TRUE(std::isnan(c.log_likelihood));
  EXPECT_NEAR(student_t_log_density(student_t_noise<1>(1.0), c.squared_distance,
                                    std::log(c.determinant), 1),
              -std::log(std::numbers::pi * std::sqrt(3.0) * 1.75), 1e-14);

  // An innovation 10 sigma out: its noise is taken (10^2 + 1) / 2 times wider, so the state moves
  // by a sixteenth of the Gaussian update's correction.
  Matrix<2> p_far = Vector<2>(2.1, 4.2).asDiagonal();
  Matrix<2> p_gauss = p_far;
  const double far = 10.0 * std::sqrt(3.0);
  const auto robust =
      update_covariance_student_t<2, 1>(p_far, h, r, Vector<1>(far), student_t_noise<1>(1.0));
  const auto plain = update_covariance<2, 1>(p_gauss, h, r, Vector<1>(far));
  EXPECT_NEAR(robust.correction[0], far * 2.1 / (2.1 + 0.9 * 101.0 / 2.0), 1e-12);
  EXPECT_LT(robust.correction[0], 0.1 * plain.correction[0]);
  EXPECT_GT(p_far(0, 0), p_gauss(0, 0));  // and learns less from it
}

TEST(LinearKalman, StudentTTendsToTheGaussianAsItsDegreesOfFreedomGrow) {
  // Three correlated components, as the rotation filters use it.
  Matrix<3> p;
  p << 2.0, 0.3, -0.2, 0.3, 1.5, 0.4, -0.2, 0.4, 0.8;
  const Matrix<3> h = Matrix<3>::Identity();
  const Matrix<3> r = 0.4 * Matrix<3>::Identity();
  const Vector<3> innovation(0.5, -0.3, 0.2);
  Matrix<3> p_gauss = p, p_t = p;
  const auto gaussian = update_covariance<3, 3>(p_gauss, h, r, innovation);
  // At 10^6 degrees of freedom R is scaled by 1 + (d^2 - 3) / (10^6 + 3), and the densities
  // differ by O(d^4 / 10^6): a few parts in a million.
  const StudentTNoise noise = student_t_noise<3>(1e6);
  const auto t = update_covariance_student_t<3, 3>(p_t, h, r, innovation, noise);
  EXPECT_NEAR(t.determinant, (p + r).determinant(), 1e-12);
  EXPECT_NEAR(gaussian.determinant, t.determinant, 1e-15);
  EXPECT_NEAR(student_t_log_density(noise, t.squared_distance, std::log(t.determinant), 3),
              gaussian.log_likelihood, 1e-5);
  const double d2 = innovation.dot((p + r).inverse() * innovation);
  EXPECT_NEAR(gaussian.squared_distance, d2, 1e-12);
  EXPECT_NEAR(t.squared_distance, d2, 1e-12);
  EXPECT_TRUE(t.correction.isApprox(gaussian.correction, 1e-5));
  EXPECT_TRUE(p_t.isApprox(p_gauss, 1e-5));
}

TEST(LinearKalman, KinematicBlocksAreTheExactDiscretisation) {
  const double q = 0.7, dt = 0.2;
  const Matrix<6> noise = white_noise_acceleration(q, dt);
  EXPECT_DOUBLE_EQ(noise(0, 0), q * q * dt * dt * dt / 3.0);
  EXPECT_DOUBLE_EQ(noise(2, 5), q * q * dt * dt / 2.0);
  EXPECT_DOUBLE_EQ(noise(5, 2), q * q * dt * dt / 2.0);
  EXPECT_DOUBLE_EQ(noise(4, 4), q * q * dt);
  EXPECT_EQ(noise(0, 1), 0.0);
  EXPECT_EQ(noise(0, 4), 0.0);

  Eigen::Matrix3d block;
  block << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const Matrix<6> f = constant_rate_transition(block, dt);
  EXPECT_TRUE((f.topLeftCorner<3, 3>() == block));
  EXPECT_TRUE((f.topRightCorner<3, 3>() == dt * Eigen::Matrix3d::Identity()));
  EXPECT_TRUE((f.bottomLeftCorner<3, 3>() == Eigen::Matrix3d::Zero()));
  EXPECT_TRUE((f.bottomRightCorner<3, 3>() == Eigen::Matrix3d::Identity()));
}

}  // namespace
}  // namespace opf::kalman
