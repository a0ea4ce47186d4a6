#pragma once
// What moves a hidden object's particles, one source per hypothesis of the Object Permanence
// Filter (paper Sec. III-B): the banks' predictive mixture (bank_mixture_motion.h), the paper's
// fitted trajectory (trajectory_motion.h), the occluder that carries it (occluder_carry.h), or
// nothing (HeldMotion: the random walk). Each hidden frame the filter asks its source for one step
// and reports what the step says: the mode, the trace of Q~ and the model label.

#include "opf/core/estimate_mode.h"
#include "opf/core/estimator.h"
#include "opf/core/recovery_events.h"
#include "opf/particles/pose_particle_filter.h"
#include "opf/permanence/covariance_inflation.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <string>

namespace opf {

/// What one hidden step left for the estimate.
struct HiddenStep {
  double observation_trace = 0.0;  ///< trace(Q~) (paper Eq. 15)
  RecoveryEvents recovery;
};

class HiddenMotion {
 public:
  virtual ~HiddenMotion() = default;
  virtual std::unique_ptr<HiddenMotion> clone() const = 0;

  /// Moves (and, for a virtual measurement, reweights and resamples) the particles from
  /// t_previous to t.
  virtual HiddenStep step(double t_previous, double t, const EnsembleView& ensemble,
                          PoseParticleFilter& filter) = 0;
  virtual EstimateMode mode() const = 0;
  /// The model behind the motion, for the estimate file's `model` column ("" when none).
  virtual std::string label() const { return {}; }
  /// Where the object's carrier (label()) is from the object, as the carry put it this step (the
  /// carrier's position less the virtual measurement's). None when nothing carries it.
  virtual std::optional<Eigen::Vector3d> carrier_offset() const { return std::nullopt; }
  /// Whether the source's motion is the prior of the measurement that ends the gap: a prediction
  /// (the banks' mixture) carries the particles to the measurement's time as it did to each hidden
  /// frame's; a virtual measurement is evidence, which the measurement replaces (the filter's own
  /// random walk then steps to it, as in the paper).
  virtual bool predicts_the_measurement() const { return false; }
};

/// A source that feeds the filter a virtual measurement each hidden frame (paper Eq. 12-14): the
/// particles random-walk, are carried by the carrier's motion (carry_particles), and are
/// reweighted under Q~ = alpha Q, alpha growing by the uncertainty module.
class VirtualMeasurementMotion : public HiddenMotion {
 public:
  struct Settings {
    UncertaintyOptions uncertainty;
    bool uncertainty_module = true;  ///< off: Q~ = Q
    bool carry_particles = true;
    /// A carrier's partial view read as one (partial_view.h); off, its detection as it is.
    bool stated_noise = true;
  };

  explicit VirtualMeasurementMotion(const Settings& settings)
      : settings_(settings), inflation_(settings.uncertainty) {}

  HiddenStep step(double t_previous, double t, const EnsembleView& ensemble,
                  PoseParticleFilter& filter) final;

 protected:
  /// The virtual measurement and how its carrier moved since the previous step.
  struct Measurement {
    Eigen::Vector3d position;
    Eigen::Quaterniond orientation;
    double speed = 0.0;  ///< m/s of the carrier, for the uncertainty module
    Eigen::Vector3d carrier_from = Eigen::Vector3d::Zero();
    Eigen::Vector3d carrier_to = Eigen::Vector3d::Zero();
    Eigen::Quaterniond carrier_rotation = Eigen::Quaterniond::Identity();
    /// The object turns about its carrier (carried at an offset) rather than with it in place.
    bool about_carrier = false;
  };
  /// The virtual measurement at t, none when the source has nothing to say this frame.
  virtual std::optional<Measurement> measure(double t, const EnsembleView& ensemble) = 0;

 private:
  Settings settings_;
  CovarianceInflation inflation_;
};

/// The object stays where it was: the random walk, with Q~ inflated by the time hidden so that
/// the feedback module still sees it. Mode `predicted` when no module has anything to say, `left`
/// for the occluder module's hypothesis that the occluder left it behind.
class HeldMotion final : public VirtualMeasurementMotion {
 public:
  explicit HeldMotion(const Settings& settings, EstimateMode mode = EstimateMode::kPredicted)
      : VirtualMeasurementMotion(settings), mode_(mode) {}
  std::unique_ptr<HiddenMotion> clone() const override {
    return std::make_unique<HeldMotion>(*this);
  }
  EstimateMode mode() const override { return mode_; }

 private:
  std::optional<Measurement> measure(double, const EnsembleView&) override { return std::nullopt; }
  EstimateMode mode_;
};

}  // namespace opf
