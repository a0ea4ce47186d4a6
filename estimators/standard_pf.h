#pragma once
// The paper's baseline: the 6-DoF particle filter with no Object Permanence update. When the
// measurement is missing it predicts only, so the estimate stays where the object vanished (the
// cloud spreads by the random walk) and jumps when the object reappears.

#include "opf/core/estimator.h"
#include "opf/particles/pose_particle_filter.h"

#include <cstdint>

namespace opf {

class StandardParticleFilter final : public Estimator {
 public:
  StandardParticleFilter(const PoseParticleFilterOptions& options, std::uint64_t seed);

  std::string_view name() const override { return "pf"; }
  Estimate initialise(double t, const mrpt::poses::CPose3D& first_measurement) override;
  Estimate step(double t, const mrpt::poses::CPose3D* measurement,
                const EnsembleView& ensemble) override;

  const PoseParticleFilter& filter() const { return filter_; }
  /// Statistics of the last step's normalisation and resampling.
  const ResampleReport& last_report() const { return last_report_; }

 private:
  Estimate make_estimate(double t, EstimateMode mode, RecoveryEvents recovery = {}) const;

  PoseParticleFilter filter_;
  ResampleReport last_report_;
  double last_t_ = 0.0;
  bool initialised_ = false;
};

}  // namespace opf
