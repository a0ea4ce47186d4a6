#include "particles/random_walk_model.h"

#include "core/so3.h"

#include <vector>

namespace opf {
namespace {

Eigen::Matrix3Xd gaussian_noise(Eigen::Index count, double sigma, Random& random) {
  Eigen::Matrix3Xd noise(3, count);
  random.fill_normal({noise.data(), static_cast<std::size_t>(noise.size())});
  return noise * sigma;
}

}  // namespace

void predict_random_walk(TranslationParticles& particles, double sigma, Random& random) {
  particles.states += gaussian_noise(particles.states.cols(), sigma, random);
}

void predict_random_walk(RotationParticles& particles, double sigma, Random& random) {
  const Eigen::Matrix3Xd noise = gaussian_noise(particles.states.cols(), sigma, random);
  for (Eigen::Index i = 0; i < particles.states.cols(); ++i) {
    Eigen::Map<Eigen::Quaterniond> q(particles.states.col(i).data());
    q = (q * so3::exp(noise.col(i))).normalized();
  }
}

void scatter_around(TranslationParticles& particles, const Eigen::Vector3d& centre, double sigma,
                    Random& random) {
  particles.states = gaussian_noise(particles.states.cols(), sigma, random).colwise() + centre;
  particles.weights.reset();
}

void scatter_around(RotationParticles& particles, const Eigen::Quaterniond& centre, double sigma,
                    Random& random) {
  particles.states.colwise() = centre.normalized().coeffs();
  predict_random_walk(particles, sigma, random);
  particles.weights.reset();
}

}  // namespace opf
