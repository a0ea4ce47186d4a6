#include "opf/particles/particle_statistics.h"

#include "opf/particles/statistics_kernels.h"

#include <Eigen/Eigenvalues>

#include <array>

namespace opf {
namespace {

// The mean is the eigenvector of M's largest eigenvalue, on the w >= 0 hemisphere.
Eigen::Quaterniond principal_quaternion(const Eigen::Matrix4d& m) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(m);
  const Eigen::Vector4d v = solver.eigenvectors().col(3);  // eigenvalues ascend
  Eigen::Quaterniond mean(v[3], v[0], v[1], v[2]);         // stored x, y, z, w
  if (mean.w() < 0.0) mean.coeffs() *= -1.0;
  return mean.normalized();
}

Eigen::Matrix3d symmetric(const std::array<double, 6>& u) {
  Eigen::Matrix3d m;
  m << u[0], u[1], u[2], u[1], u[3], u[4], u[2], u[4], u[5];
  return m;
}

// Weights for the kernels: none when they are known to be uniform (after resampling).
const double* weights_or_uniform(const LogWeights& weights, Eigen::VectorXd& linear) {
  if (weights.uniform()) return nullptr;
  linear = weights.linear();
  return linear.data();
}

}  // namespace

TranslationMoments translation_moments(const TranslationParticles& particles) {
  Eigen::VectorXd linear;
  const double* w = weights_or_uniform(particles.weights, linear);
  // About the first particle: sums of small offsets keep full precision far from the origin.
  const Eigen::Vector3d reference = particles.states.col(0);
  const kernels::TranslationSums s = kernels::translation_sums(
      particles.states.data(), particles.size(), w, {reference.x(), reference.y(), reference.z()});
  const Eigen::Vector3d offset = Eigen::Vector3d(s.first[0], s.first[1], s.first[2]) / s.weight;
  const Eigen::Matrix3d covariance = symmetric(s.second) / s.weight - offset * offset.transpose();
  return {reference + offset, covariance};
}

Eigen::Quaterniond markley_mean(const Eigen::Matrix4Xd& quaternions,
                                const Eigen::VectorXd& weights) {
  // Weighted by w (not w^2): M is the weighted second moment of the quaternions.
  return principal_quaternion(quaternions * weights.asDiagonal() * quaternions.transpose());
}

RotationMoments rotation_moments(const RotationParticles& particles) {
  Eigen::VectorXd linear;
  const double* w = weights_or_uniform(particles.weights, linear);
  const std::size_t n = particles.size();
  const double total = w ? linear.sum() : static_cast<double>(n);
  const std::array<double, 10> u = kernels::quaternion_second_moment(particles.states.data(), n, w);
  Eigen::Matrix4d m;
  m << u[0], u[1], u[2], u[3], u[1], u[4], u[5], u[6], u[2], u[5], u[7], u[8], u[3], u[6], u[8],
      u[9];
  const Eigen::Quaterniond mean = principal_quaternion(m);
  const std::array<double, 6> c = kernels::tangent_second_moment(
      particles.states.data(), n, w, {-mean.x(), -mean.y(), -mean.z(), mean.w()});
  return {mean, symmetric(c) / total};
}

}  // namespace opf
