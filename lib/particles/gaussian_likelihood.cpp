#include "opf/particles/gaussian_likelihood.h"

#include "opf/particles/likelihood_kernels.h"

namespace opf {

double reweight_gaussian(TranslationParticles& particles, const Eigen::Vector3d& measurement,
                         double variance) {
  bool accumulate = true;
  double* log_w = particles.weights.for_likelihood(accumulate);
  return kernels::translation_exponents(particles.states.data(), particles.size(),
                                        {measurement.x(), measurement.y(), measurement.z()},
                                        -0.5 / variance, log_w, accumulate);
}

namespace {

std::array<double, 3> per_axis_scales(const Eigen::Vector3d& variances) {
  return {-0.5 / variances.x(), -0.5 / variances.y(), -0.5 / variances.z()};
}

// One variance on every axis takes the scalar kernel: the same Q, bit for bit as a scalar one.
bool isotropic(const Eigen::Vector3d& variances) {
  return variances.x() == variances.y() && variances.y() == variances.z();
}

}  // namespace

double reweight_gaussian(TranslationParticles& particles, const Eigen::Vector3d& measurement,
                         const Eigen::Vector3d& variances) {
  if (isotropic(variances)) return reweight_gaussian(particles, measurement, variances.x());
  bool accumulate = true;
  double* log_w = particles.weights.for_likelihood(accumulate);
  return kernels::translation_exponents(particles.states.data(), particles.size(),
                                        {measurement.x(), measurement.y(), measurement.z()},
                                        per_axis_scales(variances), log_w, accumulate);
}

double gaussian_exponents(const TranslationParticles& particles, const Eigen::Vector3d& measurement,
                          const Eigen::Vector3d& variances, Eigen::VectorXd& exponents) {
  if (isotropic(variances))
    return gaussian_exponents(particles, measurement, variances.x(), exponents);
  exponents.resize(particles.states.cols());
  return kernels::translation_exponents(particles.states.data(), particles.size(),
                                        {measurement.x(), measurement.y(), measurement.z()},
                                        per_axis_scales(variances), exponents.data(), false);
}

double reweight_gaussian(RotationParticles& particles, const Eigen::Quaterniond& measurement,
                         double variance) {
  const Eigen::Quaterniond z = measurement.normalized();
  bool accumulate = true;
  double* log_w = particles.weights.for_likelihood(accumulate);
  return kernels::rotation_exponents(particles.states.data(), particles.size(),
                                     {z.x(), z.y(), z.z(), z.w()}, -0.5 / variance, log_w,
                                     accumulate);
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
