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
  }
  rotation_members_.resize(filter.rotation().size());
  for (std::uint16_t& m : rotation_members_) m = draw(rotation.sample_member(random_.uniform()));
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
    std::vector<MemberPrediction>& members =
        out.translation.axes[static_cast<std::size_t>(axis)].members;
    members.resize(translation.members(axis).size());
    for (std::size_t j = 0; j < members.size(); ++j)
      members[j] = translation.member_prediction(axis, j, horizon);
  }
  out.rotation.resize(rotation.members().size());
  for (std::size_t j = 0; j < out.rotation.size(); ++j)
    out.rotation[j] = rotation.member_prediction(j, horizon);
}

double MixtureParticleMotion::mixture_trace(const Predictions& p) {
  double trace = p.translation.variance().sum();
  for (const RotationMemberPrediction& member : p.rotation)
    trace += member.weight * member.covariance.trace();
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
    const std::vector<MemberPrediction>& before = from.translation.axes[axis].members;
    const std::vector<MemberPrediction>& after = to.translation.axes[axis].members;
    const std::size_t count = before.size();
    std::array<double, 64> shift{}, spread{};
    if (count > shift.size()) throw std::logic_error("MixtureParticleMotion: too many members");
    for (std::size_t j = 0; j < count; ++j) {
      shift[j] = after[j].mean - before[j].mean;
      spread[j] = std::sqrt(std::max(0.0, after[j].variance - before[j].variance));
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
  const std::size_t count = from.rotation.size();
  std::vector<Eigen::Quaterniond> turn(count);
  std::vector<double> spread(count);
  bool turns = false;
  for (std::size_t j = 0; j < count; ++j) {
    turn[j] = (to.rotation[j].orientation * from.rotation[j].orientation.conjugate()).normalized();
    turns = turns || turn[j].vec().squaredNorm() > 0.0;
    spread[j] = std::sqrt(std::max(
        0.0, (to.rotation[j].covariance.trace() - from.rotation[j].covariance.trace()) / 3.0));
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
