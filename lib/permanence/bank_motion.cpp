#include "opf/permanence/bank_motion.h"

#include <algorithm>

namespace opf {

BankMotion::BankMotion(const MotionModelBank& translation, const RotationModelBank& rotation,
                       PoseParticleFilter& filter, const UncertaintyOptions& uncertainty,
                       bool uncertainty_module, std::uint64_t seed)
    : translation_(translation),
      rotation_(rotation),
      motion_(seed),
      max_scale_(uncertainty.max_scale),
      uncertainty_module_(uncertainty_module) {
  motion_.start(translation_, rotation_, filter);
  label_ = MixtureParticleMotion::label(translation_, rotation_);
}

HiddenStep BankMotion::step(double t_previous, double t, const EnsembleView&,
                            PoseParticleFilter& filter) {
  // The particles ARE the prediction: moved along the mixture with no virtual measurement
  // pulling them back onto it (that would claim the model's own output as evidence).
  const double last = translation_.last_time();
  motion_.advance(translation_, rotation_, t_previous - last, t - last, filter);
  const double q = filter.observation_trace(1.0);
  const double cap = (max_scale_ - 1.0) * q;
  const double added = motion_.added_trace();
  if (!uncertainty_module_) return {q, {}};
  return {q + std::min(added, cap), {.trace_capped = added >= cap}};
}

std::string BankMotion::label() const {
  return MixtureParticleMotion::label(translation_, rotation_);
}

}  // namespace opf
