#pragma once
// Lets MRPT drive our filter: one portion of a PoseParticleFilter behind
// mrpt::bayes::CParticleFilterCapable, so CParticleFilter::executeOn can run it (one executeOn per
// portion and frame). The measurement arrives as an mrpt::obs::CObservationRobotPose in the
// sensory frame; no such observation means the object is unobserved (predict only).

#include "opf/particles/pose_particle_filter.h"

#include <mrpt/bayes/CParticleFilterCapable.h>

#include <cstddef>
#include <vector>

namespace opf {

enum class PortionKind { kTranslation, kRotation };

class MrptPortionAdapter : public mrpt::bayes::CParticleFilterCapable {
 public:
  MrptPortionAdapter(PoseParticleFilter& filter, PortionKind portion);

  /// Seconds elapsed since the previous step. MRPT's actions and observations carry no elapsed
  /// time for a random-walk model, so the caller sets it before each executeOn.
  void set_time_step(double dt) { dt_ = dt; }

  double getW(std::size_t i) const override;
  void setW(std::size_t i, double log_w) override;
  std::size_t particlesCount() const override;
  /// MRPT's convention: shift so the largest log-weight is 0; returns max/min weight ratio.
  double normalizeWeights(double* out_max_log_w = nullptr) override;
  double ESS() const override;
  /// Copies the selected particles AND resets their log-weights to 0. MRPT 2.5's
  /// performResampling(opts) with the default out_particle_count = 0 (how executeOn calls it)
  /// never resets the weights itself, so without this the stale weights would survive resampling.
  void performSubstitution(const std::vector<std::size_t>& indices) override;

 protected:
  void prediction_and_update_pfStandardProposal(
      const mrpt::obs::CActionCollection* action, const mrpt::obs::CSensoryFrame* observation,
      const mrpt::bayes::CParticleFilter::TParticleFilterOptions& options) override;

 private:
  LogWeights& weights();
  const LogWeights& weights() const;

  PoseParticleFilter& filter_;
  PortionKind portion_;
  double dt_ = 0.0;
};

}  // namespace opf
