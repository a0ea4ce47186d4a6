#include "particles/particle_statistics.h"

#include "core/so3.h"

#include <Eigen/Eigenvalues>

namespace opf {

TranslationMoments translation_moments(const TranslationParticles& particles) {
  const Eigen::VectorXd w = particles.weights.linear();
  const double total = w.sum();
  const Eigen::Vector3d mean = particles.states * w / total;
  const Eigen::Matrix3Xd centred = particles.states.colwise() - mean;
  const Eigen::Matrix3d covariance = centred * w.asDiagonal() * centred.transpose() / total;
  return {mean, covariance};
}

Eigen::Quaterniond markley_mean(const Eigen::Matrix4Xd& quaternions,
                                const Eigen::VectorXd& weights) {
  // Weighted by w (not w^2): M is the weighted second moment of the quaternions.
  const Eigen::Matrix4d m = quaternions * weights.asDiagonal() * quaternions.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(m);
  const Eigen::Vector4d v = solver.eigenvectors().col(3);  // eigenvalues ascend
  Eigen::Quaterniond mean(v[3], v[0], v[1], v[2]);         // stored x, y, z, w
  if (mean.w() < 0.0) mean.coeffs() *= -1.0;
  return mean.normalized();
}

RotationMoments rotation_moments(const RotationParticles& particles) {
  const Eigen::VectorXd w = particles.weights.linear();
  const double total = w.sum();
  const Eigen::Quaterniond mean = markley_mean(particles.states, w);
  const Eigen::Quaterniond mean_inverse = mean.conjugate();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < particles.states.cols(); ++i) {
    const Eigen::Quaterniond q(particles.states.col(i).data());
    const Eigen::Vector3d d = so3::log(mean_inverse * q);
    covariance.noalias() += w[i] * d * d.transpose();
  }
  return {mean, covariance / total};
}

}  // namespace opf
