#include "particles/gaussian_likelihood.h"

namespace opf {

double reweight_gaussian(TranslationParticles& particles, const Eigen::Vector3d& measurement,
                         double variance) {
  return kernels::translation_exponents(particles.states.data(), particles.size(),
                                        {measurement.x(), measurement.y(), measurement.z()},
                                        -0.5 / variance, particles.weights.log().data(), true);
}

double reweight_gaussian(RotationParticles& particles, const Eigen::Quaterniond& measurement,
                         double variance) {
  const Eigen::Quaterniond z = measurement.normalized();
  return kernels::rotation_exponents(particles.states.data(), particles.size(),
                                     {z.x(), z.y(), z.z(), z.w()}, -0.5 / variance,
                                     particles.weights.log().data(), true);
}

double gaussian_exponents(const TranslationParticles& particles, const Eigen::Vector3d& measurement,
                          double variance, Eigen::VectorXd& exponents) {
  exponents.resize(particles.states.cols());
  return kernels::translation_exponents(particles.states.data(), particles.size(),
                                        {measurement.x(), measurement.y(), measurement.z()},
                                        -0.5 / variance, exponents.data(), false);
}

double gaussian_exponents(const RotationParticles& particles, const Eigen::Quaterniond& measurement,
                          double variance, Eigen::VectorXd& exponents) {
  const Eigen::Quaterniond z = measurement.normalized();
  exponents.resize(particles.states.cols());
  return kernels::rotation_exponents(particles.states.data(), particles.size(),
                                     {z.x(), z.y(), z.z(), z.w()}, -0.5 / variance,
                                     exponents.data(), false);
}

}  // namespace opf
