#pragma once
// The dynamics module's default source: the particles follow the motion-model banks' predictive
// mixture (mixture_particle_motion.h) from the banks' state at the last measurement. Q~ is Q plus
// the covariance the mixture added since then, capped where the uncertainty module caps it.

#include "opf/permanence/covariance_inflation.h"
#include "opf/permanence/hidden_motion.h"
#include "opf/permanence/mixture_particle_motion.h"

namespace opf {

class BankMotion final : public HiddenMotion {
 public:
  /// Draws the particles' members (`seed`: this gap's draws). `uncertainty_module` off: Q~ = Q.
  BankMotion(const MotionModelBank& translation, const RotationModelBank& rotation,
             PoseParticleFilter& filter, const UncertaintyOptions& uncertainty,
             bool uncertainty_module, std::uint64_t seed);

  std::unique_ptr<HiddenMotion> clone() const override {
    return std::make_unique<BankMotion>(*this);
  }
  HiddenStep step(double t_previous, double t, const EnsembleView& ensemble,
                  PoseParticleFilter& filter) override;
  EstimateMode mode() const override { return EstimateMode::kDynamics; }
  std::string label() const override;
  bool predicts_the_measurement() const override { return true; }

 private:
  // The banks as the last measurement left them: nothing updates them while the object is hidden.
  MotionModelBank translation_;
  RotationModelBank rotation_;
  MixtureParticleMotion motion_;
  double max_scale_;
  bool uncertainty_module_;
  std::string label_;  ///< the most probable models (the weights are fixed while hidden)
};

}  // namespace opf
