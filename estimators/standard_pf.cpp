#include "opf/estimators/standard_pf.h"

#include "opf/core/pose_conversion.h"

#include <sstream>
#include <stdexcept>

namespace opf {

StandardParticleFilter::StandardParticleFilter(const PoseParticleFilterOptions& options,
                                               std::uint64_t seed)
    : filter_(options, seed) {}

Estimate StandardParticleFilter::initialise(double t, const mrpt::poses::CPose3D& first) {
  filter_.initialise(translation_of(first), orientation_of(first));
  last_t_ = t;
  initialised_ = true;
  last_report_ = {};
  return make_estimate(t, EstimateMode::kMeasured);
}

Estimate StandardParticleFilter::step(double t, const mrpt::poses::CPose3D* measurement,
                                      const EnsembleView& ensemble) {
  if (!initialised_) throw std::logic_error("StandardParticleFilter::step before initialise");
  if (!(t > last_t_)) {
    std::ostringstream msg;
    msg << "StandardParticleFilter: time " << t << " s does not follow " << last_t_ << " s";
    throw std::invalid_argument(msg.str());
  }
  filter_.predict(t - last_t_);
  last_t_ = t;
  RecoveryEvents recovery;
  if (measurement) {
    filter_.set_translation_extra_noise(stated_extra_noise(ensemble, measurement));
    recovery.sensor_reset =
        filter_.update_with_measurement(translation_of(*measurement), orientation_of(*measurement));
  }
  last_report_ = filter_.normalise_and_resample();
  recovery.weights_underflow = last_report_.weights_underflow();
  return make_estimate(t, measurement ? EstimateMode::kMeasured : EstimateMode::kPredicted,
                       recovery);
}

Estimate StandardParticleFilter::make_estimate(double t, EstimateMode mode,
                                               RecoveryEvents recovery) const {
  Estimate estimate;
  estimate.t = t;
  estimate.pose = filter_.estimate();
  estimate.observation_trace = filter_.observation_trace();
  estimate.mode = mode;
  estimate.recovery = recovery;
  return estimate;
}

}  // namespace opf
