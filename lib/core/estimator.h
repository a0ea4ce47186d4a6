#pragma once
// The interface every estimator implements (standard PF, OPF, constant-velocity Kalman, ...).
// A Tracker owns one estimator per object and steps them frame by frame.

#include "opf/core/estimate.h"
#include "opf/core/frame.h"

#include <mrpt/poses/CPose3D.h>

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opf {

/// An object's size as its detections last stated it: its silhouette's radius (m,
/// Detection::radius) and its bounding box (m, Detection::box), each zero where never stated.
struct StatedRadius {
  std::string object;
  double radius = 0.0;
  Eigen::Vector3d box = Eigen::Vector3d::Zero();
};

/// Read-only view of the whole ensemble at the frame being processed: the current detections of
/// every object, every object's estimate from the previous frame, and the sizes the detections
/// have stated so far (this frame's included; an object hidden now keeps its last). Estimators
/// that reason about other objects (the OPF's occluder module) read it; the others ignore it.
struct EnsembleView {
  const Frame& frame;
  std::span<const Estimate> previous_estimates;
  std::span<const StatedRadius> stated_radii = {};
};

/// The time step from `previous` to `t` (s); throws std::invalid_argument naming `estimator` when
/// `t` does not follow `previous`, so a filter is never stepped backwards or by zero.
double time_step(std::string_view estimator, double previous, double t);

/// m: the extra noise the detector states for `measurement` (Detection::extra_noise of the view's
/// detection whose pose it points at, as the Tracker passes them); 0 for nullptr or a pose from
/// anywhere else.
double stated_extra_noise(const EnsembleView& view, const mrpt::poses::CPose3D* measurement);

/// m: the radius `object`'s detections last stated in `view`; 0 if they never stated one.
double stated_radius(const EnsembleView& view, std::string_view object);

/// m: the bounding box `object`'s detections last stated in `view`; zero if they never stated one.
Eigen::Vector3d stated_box(const EnsembleView& view, std::string_view object);

/// The observation noise of one detection (m or rad): the configured sigma and the detection's
/// stated extra noise, independent errors, added in variance: sqrt(configured^2 + extra^2).
double observation_sigma(double configured, double extra_noise);

class Estimator {
 public:
  virtual ~Estimator() = default;

  /// The registry name, e.g. "pf" or "cvkf".
  virtual std::string_view name() const = 0;

  /// Starts the estimate at the object's first detection and returns the estimate for that frame.
  virtual Estimate initialise(double t, const mrpt::poses::CPose3D& first_measurement) = 0;

  /// Advances to time `t` (seconds, later than the previous call) and returns the estimate.
  /// `measurement` is nullptr when the object is unobserved in this frame.
  virtual Estimate step(double t, const mrpt::poses::CPose3D* measurement,
                        const EnsembleView& ensemble) = 0;

  /// The further hypotheses of the same object after the last step (hypothesis ids 1, 2, ...),
  /// e.g. the OPF's virtual object following a second, equally likely occluder. Most estimators
  /// keep none.
  virtual std::vector<Estimate> extra_hypotheses() const { return {}; }
};

}  // namespace opf
