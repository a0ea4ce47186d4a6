#pragma once
// The paper's dynamics module (Eq. 12): the polynomial fitted to the last H estimates at onset
// (fit/trajectory_fit.h), extrapolated as the virtual measurement of every hidden frame.

#include "opf/fit/trajectory_fit.h"
#include "opf/permanence/hidden_motion.h"

namespace opf {

class TrajectoryMotion final : public VirtualMeasurementMotion {
 public:
  /// `last_seen`: the time of the last measurement, where the carrier's motion starts.
  TrajectoryMotion(const Settings& settings, TrajectoryModel model, double last_seen);

  std::unique_ptr<HiddenMotion> clone() const override {
    return std::make_unique<TrajectoryMotion>(*this);
  }
  EstimateMode mode() const override { return EstimateMode::kDynamics; }

 private:
  std::optional<Measurement> measure(double t, const EnsembleView& ensemble) override;

  TrajectoryModel model_;
  Eigen::Vector3d last_position_;
  Eigen::Quaterniond last_orientation_;
};

}  // namespace opf
