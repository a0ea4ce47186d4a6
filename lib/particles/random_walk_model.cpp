#include "particles/random_walk_model.h"

#include <stdexcept>

namespace opf {
namespace {

void require_size(const Eigen::VectorXd& sigma, std::size_t count) {
  if (static_cast<std::size_t>(sigma.size()) != count)
    throw std::invalid_argument("predict_random_walk: one spread per particle needed");
}

}  // namespace

void predict_random_walk(TranslationParticles& particles, double sigma, GaussianSampler& noise) {
  const std::size_t count = static_cast<std::size_t>(particles.states.size());
  kernels::add_scaled_noise(particles.states.data(), noise.draw(count).data(), sigma, count);
}

void predict_random_walk(RotationParticles& particles, double sigma, GaussianSampler& noise) {
  const std::size_t n = particles.size();
  kernels::perturb_quaternions(particles.states.data(), n, noise.draw(3 * n).data(), sigma,
                               nullptr);
}

void predict_random_walk(TranslationParticles& particles, const Eigen::VectorXd& sigma,
                         GaussianSampler& noise) {
  const std::size_t n = particles.size();
  require_size(sigma, n);
  kernels::add_scaled_noise_per_particle(particles.states.data(), noise.draw(3 * n).data(),
                                         sigma.data(), 3, n);
}

void predict_random_walk(RotationParticles& particles, const Eigen::VectorXd& sigma,
                         GaussianSampler& noise) {
  const std::size_t n = particles.size();
  require_size(sigma, n);
  kernels::perturb_quaternions(particles.states.data(), n, noise.draw(3 * n).data(), 0.0,
                               sigma.data());
}

void scatter_around(TranslationParticles& particles, const Eigen::Vector3d& centre, double sigma,
                    GaussianSampler& noise) {
  particles.states.colwise() = centre;
  predict_random_walk(particles, sigma, noise);
  particles.weights.reset();
}

void scatter_around(RotationParticles& particles, const Eigen::Quaterniond& centre, double sigma,
                    GaussianSampler& noise) {
  particles.states.colwise() = centre.normalized().coeffs().cast<float>();
  predict_random_walk(particles, sigma, noise);
  particles.weights.reset();
}

void rotate_all(RotationParticles& particles, const Eigen::Quaterniond& r) {
  const Eigen::Quaterniond unit = r.normalized();
  kernels::rotate_quaternions(particles.states.data(), particles.size(),
                              {unit.x(), unit.y(), unit.z(), unit.w()});
}

}  // namespace opf
