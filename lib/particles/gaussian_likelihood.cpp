#include "particles/gaussian_likelihood.h"

#include "core/so3.h"

namespace opf {

double reweight_gaussian(TranslationParticles& particles, const Eigen::Vector3d& measurement,
                         double variance) {
  const double scale = -0.5 / variance;
  const Eigen::VectorXd exponents =
      ((particles.states.colwise() - measurement).colwise().squaredNorm() * scale).transpose();
  particles.weights.add(exponents);
  return exponents.maxCoeff();
}

double reweight_gaussian(RotationParticles& particles, const Eigen::Quaterniond& measurement,
                         double variance) {
  const double scale = -0.5 / variance;
  Eigen::VectorXd log_likelihood(particles.states.cols());
  for (Eigen::Index i = 0; i < particles.states.cols(); ++i) {
    const Eigen::Quaterniond q(particles.states.col(i).data());
    log_likelihood[i] = scale * so3::difference(q, measurement).squaredNorm();
  }
  particles.weights.add(log_likelihood);
  return log_likelihood.maxCoeff();
}

}  // namespace opf
