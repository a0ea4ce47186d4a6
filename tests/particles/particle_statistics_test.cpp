#include "opf/particles/particle_statistics.h"

#include "opf/core/random.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opf {
namespace {

Eigen::Vector4d coeffs(const Eigen::Quaterniond& q) {
  return q.coeffs();
}

TEST(MarkleyMean, SymmetricPairAveragesToTheMiddle) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 1, 0).normalized();
  const Eigen::Quaterniond centre = so3::exp(Eigen::Vector3d(0.2, -0.4, 0.9));
  Eigen::Matrix4Xd q(4, 2);
  q.col(0) = coeffs(centre * so3::exp(axis * 0.3));
  q.col(1) = coeffs(centre * so3::exp(-axis * 0.3));
  EXPECT_LT(so3::angle_between(markley_mean(q, Eigen::Vector2d(0.5, 0.5)), centre), 1e-12);
}

TEST(MarkleyMean, QuaternionSignDoesNotMatter) {
  const Eigen::Vector3d axis(0, 0, 1);
  Eigen::Matrix4Xd q(4, 2);
  q.col(0) = coeffs(so3::exp(axis * 0.3));
  q.col(1) = -coeffs(so3::exp(axis * 0.5));  // the same rotation as +q: naive averaging breaks
  const Eigen::Quaterniond mean = markley_mean(q, Eigen::Vector2d(0.5, 0.5));
  EXPECT_LT(so3::angle_between(mean, so3::exp(axis * 0.4)), 1e-12);
}

TEST(MarkleyMean, WeightedPairMatchesTheClosedForm) {
  // Two rotations about one axis, angles 0 and theta: M's top eigenvector lies in their plane at
  // half-angle psi with tan(2 psi) = w2 sin(theta) / (w1 + w2 cos(theta)), i.e. rotation 2 psi.
  const double theta = 1.2, w1 = 0.75, w2 = 0.25;
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  Eigen::Matrix4Xd q(4, 2);
  q.col(0) = coeffs(Eigen::Quaterniond::Identity());
  q.col(1) = coeffs(so3::exp(axis * theta));
  const double expected = std::atan2(w2 * std::sin(theta), w1 + w2 * std::cos(theta));
  const Eigen::Quaterniond mean = markley_mean(q, Eigen::Vector2d(w1, w2));
  EXPECT_LT((so3::log(mean) - axis * expected).norm(), 1e-12);
}

TEST(MarkleyMean, AveragesAcrossPi) {
  // Rotations of pi - 0.1 and pi + 0.1 about z straddle the +-pi seam; their mean is pi about z.
  const Eigen::Vector3d z(0, 0, 1);
  Eigen::Matrix4Xd q(4, 2);
  q.col(0) = coeffs(so3::exp(z * (std::numbers::pi - 0.1)));
  q.col(1) = coeffs(so3::exp(z * (std::numbers::pi + 0.1)));
  const Eigen::Quaterniond mean = markley_mean(q, Eigen::Vector2d(0.5, 0.5));
  EXPECT_NEAR(so3::angle_between(mean, so3::exp(z * std::numbers::pi)), 0.0, 1e-12);
}

TEST(RotationMoments, TangentCovarianceOfAGaussianCloud) {
  // Particles q_i = c * exp(e_i), e_i ~ N(0, diag(s^2)): mean ~ c, covariance ~ diag(s^2).
  // With N = 20000 the sample variance's relative error is sqrt(2/N) = 1%; allow 5%.
  const Eigen::Vector3d sigma(0.05, 0.1, 0.2);
  const Eigen::Quaterniond centre = so3::exp(Eigen::Vector3d(1.0, 0.2, -0.3));
  RotationParticles particles;
  particles.resize(20000);
  Random random(9);
  for (Eigen::Index i = 0; i < particles.states.cols(); ++i) {
    const Eigen::Vector3d e(sigma.x() * random.normal(), sigma.y() * random.normal(),
                            sigma.z() * random.normal());
    particles.states.col(i) = coeffs(centre * so3::exp(e)).cast<float>();
  }
  const RotationMoments m = rotation_moments(particles);
  EXPECT_LT(so3::angle_between(m.mean, centre), 5.0 * sigma.z() / std::sqrt(20000.0));
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(m.tangent_covariance(k, k), sigma[k] * sigma[k], 0.05 * sigma[k] * sigma[k]);
  EXPECT_NEAR(m.tangent_covariance(0, 2), 0.0, 5.0 * sigma.x() * sigma.z() / std::sqrt(20000.0));
}

TEST(TranslationMoments, WeightedMeanAndCovariance) {
  TranslationParticles particles;
  particles.resize(2);
  particles.states.col(0) = Eigen::Vector3d(0, 0, 0);
  particles.states.col(1) = Eigen::Vector3d(4, 0, 0);
  particles.weights.log() << std::log(0.75), std::log(0.25);
  const TranslationMoments m = translation_moments(particles);
  EXPECT_NEAR(m.mean.x(), 1.0, 1e-15);
  EXPECT_NEAR(m.covariance(0, 0), 0.75 * 1.0 + 0.25 * 9.0, 1e-14);
  EXPECT_NEAR(m.covariance(1, 1), 0.0, 1e-15);
}

}  // namespace
}  // namespace opf
