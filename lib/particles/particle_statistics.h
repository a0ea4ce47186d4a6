#pragma once
// Weighted statistics of the particle portions: translation mean and covariance, the Markley
// quaternion mean and the rotation covariance in the tangent space at that mean.

#include "opf/particles/particle_portion.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace opf {

struct TranslationMoments {
  Eigen::Vector3d mean;
  Eigen::Matrix3d covariance;
};

struct RotationMoments {
  Eigen::Quaterniond mean;
  Eigen::Matrix3d tangent_covariance;  ///< of log(mean^-1 q_i), body frame
};

/// Weighted mean and (biased, weight-normalised) covariance of the translation particles.
TranslationMoments translation_moments(const TranslationParticles& particles);

/// Markley et al. (2007) average: the eigenvector of the largest eigenvalue of
/// M = sum w_i q_i q_i^T. Insensitive to the q/-q sign ambiguity, unlike averaging components.
Eigen::Quaterniond markley_mean(const Eigen::Matrix4Xd& quaternions,
                                const Eigen::VectorXd& weights);

/// Markley mean and the weighted covariance of the particles' tangent vectors about it.
RotationMoments rotation_moments(const RotationParticles& particles);

}  // namespace opf
