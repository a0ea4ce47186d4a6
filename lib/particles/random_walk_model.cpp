#include "opf/particles/random_walk_model.h"

#include "opf/particles/member_table_step.h"
#include "opf/particles/motion_kernels.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace opf {
namespace {

// Noise is drawn and used in chunks of particles, so the samples stay in the L1 cache instead of
// making a pass through memory of their own (three floats per particle per portion).
constexpr std::size_t kChunk = 1024;

void require_size(const Eigen::VectorXd& sigma, std::size_t count) {
  if (static_cast<std::size_t>(sigma.size()) != count)
    throw std::invalid_argument("predict_random_walk: one spread per particle needed");
}

// Translation rows: x[r n + i] += s n_ri, chunk by chunk, with s = row_sigma(r), or the
// particle's own spread per_particle[i] when that is given.
void add_noise(TranslationParticles& particles, const Eigen::Vector3d& row_sigma,
               const double* per_particle, GaussianSampler& noise,
               const Eigen::Vector3d* offset = nullptr) {
  const std::size_t n = particles.size();
  alignas(64) std::array<float, kChunk> block;
  for (std::size_t r = 0; r < 3; ++r) {
    double* row = particles.states.data() + r * n;
    for (std::size_t begin = 0; begin < n; begin += kChunk) {
      const std::size_t count = std::min(kChunk, n - begin);
      noise.fill({block.data(), count});
      if (offset)
        kernels::add_offset_and_scaled_noise(row + begin, block.data(),
                                             (*offset)(static_cast<Eigen::Index>(r)),
                                             row_sigma(static_cast<Eigen::Index>(r)), count);
      else if (per_particle)
        kernels::add_scaled_noise_per_particle(row + begin, block.data(), per_particle + begin,
                                               count);
      else
        kernels::add_scaled_noise(row + begin, block.data(),
                                  row_sigma(static_cast<Eigen::Index>(r)), count);
    }
  }
}

void perturb(RotationParticles& particles, double sigma, const double* per_particle,
             GaussianSampler& noise, const Eigen::Quaterniond* turn = nullptr) {
  std::array<double, 4> r{};
  if (turn) {
    const Eigen::Quaterniond unit = turn->normalized();
    r = {unit.x(), unit.y(), unit.z(), unit.w()};
  }
  const std::size_t n = particles.size();
  alignas(64) std::array<float, 3 * kChunk> block;
  for (std::size_t begin = 0; begin < n; begin += kChunk) {
    const std::size_t count = std::min(kChunk, n - begin);
    noise.fill({block.data(), 3 * count});
    if (turn)
      kernels::turn_and_perturb_quaternions(particles.states.data() + begin, n, count, block.data(),
                                            sigma, r);
    else
      kernels::perturb_quaternions(particles.states.data() + begin, n, count, block.data(), sigma,
                                   per_particle ? per_particle + begin : nullptr);
  }
}

}  // namespace

void predict_random_walk(TranslationParticles& particles, double sigma, GaussianSampler& noise) {
  add_noise(particles, Eigen::Vector3d::Constant(sigma), nullptr, noise);
}

void predict_random_walk(RotationParticles& particles, double sigma, GaussianSampler& noise) {
  perturb(particles, sigma, nullptr, noise);
}

void predict_random_walk(TranslationParticles& particles, double sigma,
                         const Eigen::Vector3d& offset, GaussianSampler& noise) {
  add_noise(particles, Eigen::Vector3d::Constant(sigma), nullptr, noise, &offset);
}

void predict_random_walk(TranslationParticles& particles, const Eigen::Vector3d& sigma,
                         const Eigen::Vector3d& offset, GaussianSampler& noise) {
  add_noise(particles, sigma, nullptr, noise, &offset);
}

void predict_random_walk(RotationParticles& particles, double sigma, const Eigen::Quaterniond& turn,
                         GaussianSampler& noise) {
  perturb(particles, sigma, nullptr, noise, &turn);
}

void predict_random_walk(TranslationParticles& particles, const Eigen::VectorXd& sigma,
                         GaussianSampler& noise) {
  require_size(sigma, particles.size());
  add_noise(particles, Eigen::Vector3d::Zero(), sigma.data(), noise);
}

void predict_random_walk(RotationParticles& particles, const Eigen::VectorXd& sigma,
                         GaussianSampler& noise) {
  require_size(sigma, particles.size());
  perturb(particles, 0.0, sigma.data(), noise);
}

void predict_row_by_member(TranslationParticles& particles, std::size_t row,
                           std::span<const std::uint8_t> members, std::span<const double> offset,
                           std::span<const double> spread, GaussianSampler& noise) {
  const std::size_t n = particles.size();
  if (row >= 3 || members.size() != n || offset.size() != spread.size() || offset.size() > 256)
    throw std::invalid_argument("predict_row_by_member: a row, a member per particle, tables");
  kernels::MemberTable offsets{}, spreads{};  // zero past the members', read by any byte
  std::copy(offset.begin(), offset.end(), offsets.begin());
  std::copy(spread.begin(), spread.end(), spreads.begin());
  alignas(64) std::array<float, kChunk> block;
  double* x = particles.states.data() + row * n;
  for (std::size_t begin = 0; begin < n; begin += kChunk) {
    const std::size_t count = std::min(kChunk, n - begin);
    noise.fill({block.data(), count});
    kernels::add_member_offset_and_noise(x + begin, block.data(), members.data() + begin, offsets,
                                         spreads, offset.size(), count);
  }
}

void predict_segments(RotationParticles& particles, std::span<const std::size_t> ends,
                      std::span<const Eigen::Quaterniond> turn, std::span<const double> spread,
                      GaussianSampler& noise) {
  const std::size_t n = particles.size();
  if (ends.size() != turn.size() || turn.size() != spread.size() ||
      !std::is_sorted(ends.begin(), ends.end()) || (!ends.empty() && ends.back() != n))
    throw std::invalid_argument("predict_segments: ascending segment ends up to N, one step each");
  alignas(64) std::array<float, 3 * kChunk> block;
  std::size_t begin = 0;
  for (std::size_t k = 0; k < ends.size(); begin = ends[k++]) {
    const Eigen::Quaterniond unit = turn[k].normalized();
    const std::array<double, 4> r{unit.x(), unit.y(), unit.z(), unit.w()};
    const bool turns = unit.vec().squaredNorm() > 0.0;
    for (std::size_t first = begin; first < ends[k]; first += kChunk) {
      const std::size_t count = std::min(kChunk, ends[k] - first);
      noise.fill({block.data(), 3 * count});
      float* q = particles.states.data() + first;
      if (turns)
        kernels::turn_and_perturb_quaternions(q, n, count, block.data(), spread[k], r);
      else
        kernels::perturb_quaternions(q, n, count, block.data(), spread[k], nullptr);
    }
  }
}

void predict_random_walk_per_axis(TranslationParticles& particles, const Eigen::Vector3d& sigma,
                                  GaussianSampler& noise) {
  add_noise(particles, sigma, nullptr, noise);
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
