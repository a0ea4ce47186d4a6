#pragma once
// The particles' motion model: a Gaussian random walk, x' = x + e with e ~ N(0, sigma^2 I) for
// translation (paper Eq. 3 with f the identity) and q' = q * exp(e) in the tangent space for
// rotation, so rotation particles stay unit quaternions on SO(3).

#include "opf/particles/gaussian_sampler.h"
#include "opf/particles/particle_portion.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <span>

namespace opf {

void predict_random_walk(TranslationParticles& particles, double sigma, GaussianSampler& noise);
void predict_random_walk(RotationParticles& particles, double sigma, GaussianSampler& noise);

/// A rigid shift (x' = x + offset + e) or a world-frame turn (q' = r q exp(e)) first, in the same
/// pass over the particles as the random walk: the velocity drift costs no pass of its own.
void predict_random_walk(TranslationParticles& particles, double sigma,
                         const Eigen::Vector3d& offset, GaussianSampler& noise);
/// The same with a spread per world axis (sigma(d) for coordinate d).
void predict_random_walk(TranslationParticles& particles, const Eigen::Vector3d& sigma,
                         const Eigen::Vector3d& offset, GaussianSampler& noise);
void predict_random_walk(RotationParticles& particles, double sigma, const Eigen::Quaterniond& turn,
                         GaussianSampler& noise);

/// The same with a spread per particle (sigma[i] for particle i).
void predict_random_walk(TranslationParticles& particles, const Eigen::VectorXd& sigma,
                         GaussianSampler& noise);
void predict_random_walk(RotationParticles& particles, const Eigen::VectorXd& sigma,
                         GaussianSampler& noise);

/// A multiple-model step: every particle moved by its own motion model. Translation, one
/// coordinate row r at a time, with m_i = members[i] an index into tables of at most 256 models
/// (a member past them does not move):
/// x' = x + offset[m_i] + spread[m_i] e. Rotation, with the particles grouped by model into
/// consecutive segments (segment k ends before particle ends[k]): q' = turn[k] q exp(spread[k] e).
void predict_row_by_member(TranslationParticles& particles, std::size_t row,
                           std::span<const std::uint8_t> members, std::span<const double> offset,
                           std::span<const double> spread, GaussianSampler& noise);
void predict_segments(RotationParticles& particles, std::span<const std::size_t> ends,
                      std::span<const Eigen::Quaterniond> turn, std::span<const double> spread,
                      GaussianSampler& noise);

/// Translation noise with its own spread per world axis (sigma(d) for coordinate d).
void predict_random_walk_per_axis(TranslationParticles& particles, const Eigen::Vector3d& sigma,
                                  GaussianSampler& noise);

/// Places every particle at `centre` perturbed by the same kind of noise (initialisation).
void scatter_around(TranslationParticles& particles, const Eigen::Vector3d& centre, double sigma,
                    GaussianSampler& noise);
void scatter_around(RotationParticles& particles, const Eigen::Quaterniond& centre, double sigma,
                    GaussianSampler& noise);

/// Turns every rotation particle by the world-frame rotation r: q <- r * q.
void rotate_all(RotationParticles& particles, const Eigen::Quaterniond& r);

}  // namespace opf
