#include "opf/permanence/hidden_motion.h"

namespace opf {

HiddenStep VirtualMeasurementMotion::step(double t_previous, double t, const EnsembleView& ensemble,
                                          PoseParticleFilter& filter) {
  const double dt = t - t_previous;
  filter.predict(dt);
  const std::optional<Measurement> z = measure(t, ensemble);
  if (z && settings_.carry_particles) {
    // Carried at an offset, the object turns about its carrier; otherwise it moves with it.
    if (z->about_carrier)
      filter.carry(z->carrier_from, z->carrier_to, z->carrier_rotation);
    else
      filter.shift(z->carrier_to - z->carrier_from, z->carrier_rotation);
  }
  // Without the uncertainty module Q~ stays Q; with it Q~ grows every hidden step, also when no
  // module supplies a virtual measurement, so the feedback module still sees the time hidden.
  if (settings_.uncertainty_module) inflation_.step(z ? z->speed : 0.0, dt);
  if (z) filter.reweight(z->position, z->orientation, inflation_.scale());
  const ResampleReport report = filter.normalise_and_resample();
  return {filter.observation_trace(inflation_.scale()),
          {.weights_underflow = report.weights_underflow(), .trace_capped = inflation_.capped()}};
}

}  // namespace opf
