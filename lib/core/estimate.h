#pragma once
// An estimator's output for one object at one frame.

#include "opf/core/estimate_mode.h"
#include "opf/core/recovery_events.h"

#include <mrpt/poses/CPose3DPDFGaussian.h>

#include <optional>
#include <string>

namespace opf {

struct Estimate {
  std::string object;
  double t = 0.0;
  /// Mean pose and its 6x6 covariance over (x, y, z, yaw, pitch, roll), MRPT's convention.
  mrpt::poses::CPose3DPDFGaussian pose;
  /// trace of the observation covariance used at this step (paper Eq. 15, U = trace(Q~)).
  double observation_trace = 0.0;
  EstimateMode mode = EstimateMode::kMeasured;
  /// What the step had to do to stay usable (sensor reset, underflow, Q~ capped): reported after
  /// the mode word in result files.
  RecoveryEvents recovery;
  /// 0 for an object's main estimate; 1, 2, ... for the further hypotheses an estimator keeps
  /// (the OPF's virtual objects O_i', one per further plausible occluder, paper Sec. III-B.2).
  int hypothesis = 0;
  /// The hypothesis's probability among the object's (1 for an object's only estimate).
  double probability = 1.0;
  /// The motion model behind the estimate, where an estimator chooses among several (the OPF's
  /// most probable bank model per axis x, y, z, then the rotation's, while hidden; the IMM's
  /// most probable model per axis); empty otherwise.
  std::string motion_model;
};

/// The feedback module's safety alert (paper Sec. III-C.1, Eq. 15): the estimate's trace of the
/// observation covariance has reached epsilon_safe, and the robot should stop, fall back to a safe
/// mode or alert the operator. It is a function of any estimator's trace, so the alert columns of
/// result files apply it to every estimator alike.
inline bool safety_alert(const Estimate& estimate, double epsilon_safe) {
  return estimate.observation_trace >= epsilon_safe;
}

}  // namespace opf
