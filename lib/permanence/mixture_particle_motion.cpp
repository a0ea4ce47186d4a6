#include "opf/permanence/mixture_particle_motion.h"

#include "opf/particles/random_walk_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace opf {
namespace {

constexpr std::uint64_t kNoiseStream = 1;

std::uint16_t draw(std::size_t member) {
  return static_cast<std::uint16_t>(member);
}

}  // namespace

MixtureParticleMotion::MixtureParticleMotion(std::uint64_t seed)
    : random_(seed), noise_(derive_seed(seed, kNoiseStream)) {}

void MixtureParticleMotion::start(const MotionModelBank& translation,
                                  const RotationModelBank& rotation,
                                  const PoseParticleFilter& filter) {
  if (!translation.initialised() || !rotation.initialised())
    throw std::logic_error("MixtureParticleMotion::start before the banks saw a measurement");
  const std::size_t n = filter.translation().size();
  for (int axis = 0; axis < 3; ++axis) {
    const auto a = static_cast<std::size_t>(axis);
    translation_members_[a].resize(n);
    for (std::uint16_t& m : translation_members_[a])
      m = draw(translation.sample_member(axis, random_.uniform()));
    const std::span<const double> w = translation.weights(axis);
    weights_[a].assign(w.begin(), w.end());
  }
  rotation_members_.resize(filter.rotation().size());
  for (std::uint16_t& m : rotation_members_) m = draw(rotation.sample_member(random_.uniform()));
  const std::span<const double> w = rotation.weights();
  rotation_weights_.assign(w.begin(), w.end());
  predict(translation, rotation, 0.0, last_);
  trace_at_onset_ = mixture_trace(last_);
}

void MixtureParticleMotion::advance(const MotionModelBank& translation,
                                    const RotationModelBank& rotation, double h0, double h1,
                                    PoseParticleFilter& filter) {
  if (!(h0 >= 0.0) || !(h1 >= h0))
    throw std::invalid_argument("MixtureParticleMotion::advance needs 0 <= h0 <= h1");
  if (translation_members_[0].size() != filter.translation().size() ||
      rotation_members_.size() != filter.rotation().size())
    throw std::logic_error("MixtureParticleMotion::advance before start");
  if (last_.horizon != h0) predict(translation, rotation, h0, last_);
  predict(translation, rotation, h1, next_);
  move_translation(last_, next_, filter.translation());
  move_rotation(last_, next_, filter.rotation());
  std::swap(last_, next_);
}

void MixtureParticleMotion::predict(const MotionModelBank& translation,
                                    const RotationModelBank& rotation, double horizon,
                                    Predictions& out) {
  out.horizon = horizon;
  for (int axis = 0; axis < 3; ++axis) {
    const auto a = static_cast<std::size_t>(axis);
    const std::size_t count = translation.members(axis).size();
    out.mean[a].resize(count);
    out.variance[a].resize(count);
    for (std::size_t j = 0; j < count; ++j) {
      const MemberPrediction p = translation.member_prediction(axis, j, horizon);
      out.mean[a][j] = p.mean;
      out.variance[a][j] = p.variance;
    }
  }
  const std::size_t count = rotation.members().size();
  out.orientation.resize(count);
  out.rotation_trace.resize(count);
  for (std::size_t j = 0; j < count; ++j) {
    const RotationMemberPrediction p = rotation.member_prediction(j, horizon);
    out.orientation[j] = p.orientation;
    out.rotation_trace[j] = p.covariance.trace();
  }
}

double MixtureParticleMotion::mixture_trace(const Predictions& p) const {
  double trace = 0.0;
  for (std::size_t a = 0; a < 3; ++a) {
    double mean = 0.0, second = 0.0;
    for (std::size_t j = 0; j < weights_[a].size(); ++j) {
      mean += weights_[a][j] * p.mean[a][j];
      second += weights_[a][j] * (p.variance[a][j] + p.mean[a][j] * p.mean[a][j]);
    }
    trace += second - mean * mean;
  }
  for (std::size_t j = 0; j < rotation_weights_.size(); ++j)
    trace += rotation_weights_[j] * p.rotation_trace[j];
  return trace;
}

double MixtureParticleMotion::added_trace() const {
  return std::max(0.0, mixture_trace(last_) - trace_at_onset_);
}

void MixtureParticleMotion::move_translation(const Predictions& from, const Predictions& to,
                                             TranslationParticles& particles) {
  const std::size_t n = particles.size();
  normals_.resize(n);
  gathered_.resize(2 * n);
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const std::size_t count = from.mean[axis].size();
    std::array<double, 64> shift{}, spread{};
    if (count > shift.size()) throw std::logic_error("MixtureParticleMotion: too many members");
    for (std::size_t j = 0; j < count; ++j) {
      shift[j] = to.mean[axis][j] - from.mean[axis][j];
      spread[j] = std::sqrt(std::max(0.0, to.variance[axis][j] - from.variance[axis][j]));
    }
    noise_.fill(normals_);
    // Each particle's member's shift and spread gathered first, so that the update is one loop
    // over contiguous rows that the compiler vectorises.
    const std::vector<std::uint16_t>& members = translation_members_[axis];
    double* __restrict offset = gathered_.data();
    double* __restrict sigma = offset + n;
    for (std::size_t i = 0; i < n; ++i) {
      offset[i] = shift[members[i]];
      sigma[i] = spread[members[i]];
    }
    double* __restrict row = particles.states.data() + axis * n;
    const float* __restrict e = normals_.data();
    for (std::size_t i = 0; i < n; ++i) row[i] += offset[i] + sigma[i] * static_cast<double>(e[i]);
  }
}

void MixtureParticleMotion::move_rotation(const Predictions& from, const Predictions& to,
                                          RotationParticles& particles) {
  using Scalar = RotationParticles::States::Scalar;
  const std::size_t count = from.orientation.size();
  std::vector<Eigen::Quaterniond> turn(count);
  std::vector<double> spread(count);
  bool turns = false;
  for (std::size_t j = 0; j < count; ++j) {
    turn[j] = (to.orientation[j] * from.orientation[j].conjugate()).normalized();
    turns = turns || turn[j].vec().squaredNorm() > 0.0;
    spread[j] = std::sqrt(std::max(0.0, (to.rotation_trace[j] - from.rotation_trace[j]) / 3.0));
  }
  const std::size_t n = particles.size();
  Eigen::VectorXd sigma(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i)
    sigma[static_cast<Eigen::Index>(i)] = spread[rotation_members_[i]];
  if (turns) {
    // q <- r q with each particle's member's turn r, gathered into rows first so that the
    // product is one loop over contiguous rows; in double, as Eigen's product, and its order.
    gathered_.resize(4 * n);
    double* __restrict rx = gathered_.data();
    double* __restrict ry = rx + n;
    double* __restrict rz = ry + n;
    double* __restrict rw = rz + n;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Quaterniond& r = turn[rotation_members_[i]];
      rx[i] = r.x();
      ry[i] = r.y();
      rz[i] = r.z();
      rw[i] = r.w();
    }
    Scalar* __restrict x = particles.states.data();
    Scalar* __restrict y = x + n;
    Scalar* __restrict z = y + n;
    Scalar* __restrict w = z + n;
    for (std::size_t i = 0; i < n; ++i) {
      const double bx = x[i], by = y[i], bz = z[i], bw = w[i];
      x[i] = static_cast<Scalar>((rw[i] * bx + ry[i] * bz) - (rz[i] * by - rx[i] * bw));
      y[i] = static_cast<Scalar>((rw[i] * by + ry[i] * bw) + (rz[i] * bx - rx[i] * bz));
      z[i] = static_cast<Scalar>((rw[i] * bz - ry[i] * bx) + (rz[i] * bw + rx[i] * by));
      w[i] = static_cast<Scalar>((rw[i] * bw - ry[i] * by) - (rz[i] * bz + rx[i] * bx));
    }
  }
  predict_random_walk(particles, sigma, noise_);
}

std::string MixtureParticleMotion::label(const MotionModelBank& translation,
                                         const RotationModelBank& rotation) {
  std::string text;
  for (int axis = 0; axis < 3; ++axis) {
    MotionModel best = MotionModel::kConstantPosition;
    double best_weight = -1.0;
    for (int m = 0; m < kMotionModelCount; ++m) {
      const double w = translation.model_weight(axis, static_cast<MotionModel>(m));
      if (w > best_weight) {
        best_weight = w;
        best = static_cast<MotionModel>(m);
      }
    }
    text += std::string(axis == 0 ? "" : ",") + std::string(model_name(best));
  }
  const bool turning = rotation.model_weight(RotationModel::kConstantAngularVelocity) >
                       rotation.model_weight(RotationModel::kConstantOrientation);
  return text + "/" +
         std::string(rotation_model_name(turning ? RotationModel::kConstantAngularVelocity
                                                 : RotationModel::kConstantOrientation));
}

}  // namespace opf
