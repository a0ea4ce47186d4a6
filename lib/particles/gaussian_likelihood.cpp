#include "particles/gaussian_likelihood.h"

#include "core/so3.h"

namespace opf {

void reweight_gaussian(TranslationParticles& particles, const Eigen::Vector3d& measurement,
                       double variance) {
  const double scale = -0.5 / variance;
  particles.weights.add(
      ((particles.states.colwise() - measurement).colwise().squaredNorm() * scale).transpose());
}

void reweight_gaussian(RotationParticles& particles, const Eigen::Quaterniond& measurement,
                       double variance) {
  const double scale = -0.5 / variance;
  Eigen::VectorXd log_likelihood(particles.states.cols());
  for (Eigen::Index i = 0; i < particles.states.cols(); ++i) {
    const Eigen::Quaterniond q(particles.states.col(i).data());
    log_likelihood[i] = scale * so3::difference(q, measurement).squaredNorm();
  }
  particles.weights.add(log_likelihood);
}

}  // namespace opf
