#pragma once
// The measurement update of paper Eq. 4-5: each particle's weight is multiplied by the Gaussian
// likelihood of the measurement, N(y; g(x), Q), with g the identity on the pose and Q = variance I
// per portion (rotation residuals in the particle's tangent space). The normalising constant is
// the same for every particle, so only the exponent is added to the log-weights.

#include "opf/particles/particle_portion.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace opf {

/// Returns the largest exponent over the particles, -0.5 d^2 / variance for the particle nearest
/// the measurement: how far the measurement is from the whole cloud (sensor resetting).
double reweight_gaussian(TranslationParticles& particles, const Eigen::Vector3d& measurement,
                         double variance);
double reweight_gaussian(RotationParticles& particles, const Eigen::Quaterniond& measurement,
                         double variance);
/// A diagonal Q: a variance per world axis (the same on every axis: the scalar overload's result).
double reweight_gaussian(TranslationParticles& particles, const Eigen::Vector3d& measurement,
                         const Eigen::Vector3d& variances);

/// The exponents alone, -0.5 d_i^2 / variance per particle, into `exponents` (weights
/// untouched); returns the largest.
double gaussian_exponents(const TranslationParticles& particles, const Eigen::Vector3d& measurement,
                          double variance, Eigen::VectorXd& exponents);
double gaussian_exponents(const RotationParticles& particles, const Eigen::Quaterniond& measurement,
                          double variance, Eigen::VectorXd& exponents);
double gaussian_exponents(const TranslationParticles& particles, const Eigen::Vector3d& measurement,
                          const Eigen::Vector3d& variances, Eigen::VectorXd& exponents);

}  // namespace opf
