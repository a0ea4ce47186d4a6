#include "opf/permanence/mixture_particle_motion.h"

#include "opf/particles/random_walk_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace opf {
namespace {

constexpr std::uint64_t kNoiseStream = 1;

std::uint8_t draw(std::size_t member) {
  if (member > 255) throw std::logic_error("MixtureParticleMotion: more than 256 members");
  return static_cast<std::uint8_t>(member);
}

}  // namespace

MixtureParticleMotion::MixtureParticleMotion(std::uint64_t seed)
    : random_(seed), noise_(derive_seed(seed, kNoiseStream)) {}

void MixtureParticleMotion::start(const MotionModelBank& translation,
                                  const RotationModelBank& rotation, PoseParticleFilter& filter) {
  if (!translation.initialised() || !rotation.initialised())
    throw std::logic_error("MixtureParticleMotion::start before the banks saw a measurement");
  const std::size_t n = filter.translation().size();
  for (int axis = 0; axis < 3; ++axis) {
    const auto a = static_cast<std::size_t>(axis);
    translation_members_[a].resize(n);
    for (std::uint8_t& m : translation_members_[a])
      m = draw(translation.sample_member(axis, random_.uniform()));
  }
  group_by_member(rotation, filter.rotation());
  predict(translation, rotation, 0.0, last_);
  trace_at_onset_ = mixture_trace(last_);
}

void MixtureParticleMotion::advance(const MotionModelBank& translation,
                                    const RotationModelBank& rotation, double h0, double h1,
                                    PoseParticleFilter& filter) {
  if (!(h0 >= 0.0) || !(h1 >= h0))
    throw std::invalid_argument("MixtureParticleMotion::advance needs 0 <= h0 <= h1");
  if (translation_members_[0].size() != filter.translation().size() || rotation_ends_.empty() ||
      rotation_ends_.back() != filter.rotation().size())
    throw std::logic_error("MixtureParticleMotion::advance before start");
  if (last_.horizon != h0) predict(translation, rotation, h0, last_);
  predict(translation, rotation, h1, next_);
  move_translation(last_, next_, filter.translation());
  move_rotation(last_, next_, filter.rotation());
  std::swap(last_, next_);
}

void MixtureParticleMotion::group_by_member(const RotationModelBank& rotation,
                                            RotationParticles& particles) {
  // Members drawn independently per particle as before; the particles are then reordered so that
  // each member's are consecutive (a counting sort, stable), weights and all. The set and its
  // weights are unchanged; the step becomes one vectorised pass per member.
  const std::size_t n = particles.size();
  std::vector<std::uint8_t> member(n);
  rotation_ends_.assign(rotation.members().size(), 0);
  for (std::uint8_t& m : member) {
    m = draw(rotation.sample_member(random_.uniform()));
    ++rotation_ends_[m];
  }
  std::vector<std::size_t> next(rotation_ends_.size(), 0);
  for (std::size_t k = 1; k < next.size(); ++k) next[k] = next[k - 1] + rotation_ends_[k - 1];
  for (std::size_t k = 0; k < next.size(); ++k) rotation_ends_[k] = next[k] + rotation_ends_[k];
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[next[member[i]]++] = i;
  const bool uniform = particles.weights.uniform();
  const Eigen::VectorXd log_weights = uniform ? Eigen::VectorXd() : particles.weights.log();
  particles.resample(order);  // a permutation: every particle once, then uniform weights
  if (uniform) return;
  Eigen::VectorXd& reordered = particles.weights.log();
  for (std::size_t i = 0; i < n; ++i)
    reordered[static_cast<Eigen::Index>(i)] = log_weights[static_cast<Eigen::Index>(order[i])];
}

void MixtureParticleMotion::predict(const MotionModelBank& translation,
                                    const RotationModelBank& rotation, double horizon,
                                    Predictions& out) {
  out.horizon = horizon;
  translation.predict(horizon, out.translation);
  rotation.predict(horizon, out.rotation);
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
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const std::vector<MemberPrediction>& before = from.translation.axes[axis].members;
    const std::vector<MemberPrediction>& after = to.translation.axes[axis].members;
    shift_.resize(before.size());
    spread_.resize(before.size());
    for (std::size_t j = 0; j < before.size(); ++j) {
      shift_[j] = after[j].mean - before[j].mean;
      spread_[j] = std::sqrt(std::max(0.0, after[j].variance - before[j].variance));
    }
    predict_row_by_member(particles, axis, translation_members_[axis], shift_, spread_, noise_);
  }
}

void MixtureParticleMotion::move_rotation(const Predictions& from, const Predictions& to,
                                          RotationParticles& particles) {
  turn_.resize(from.rotation.size());
  spread_.resize(from.rotation.size());
  for (std::size_t j = 0; j < turn_.size(); ++j) {
    turn_[j] = to.rotation[j].orientation * from.rotation[j].orientation.conjugate();
    spread_[j] = std::sqrt(std::max(
        0.0, (to.rotation[j].covariance.trace() - from.rotation[j].covariance.trace()) / 3.0));
  }
  predict_segments(particles, rotation_ends_, turn_, spread_, noise_);
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
  RotationModel likeliest = RotationModel::kConstantOrientation;
  for (const RotationModel model :
       {RotationModel::kConstantAngularVelocity, RotationModel::kDampedAngularVelocity})
    if (rotation.model_weight(model) > rotation.model_weight(likeliest)) likeliest = model;
  return text + "/" + std::string(rotation_model_name(likeliest));
}

}  // namespace opf
