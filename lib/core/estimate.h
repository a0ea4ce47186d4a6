#pragma once
// An estimator's output for one object at one frame.

#include "core/estimate_mode.h"

#include <mrpt/poses/CPose3DPDFGaussian.h>

#include <string>

namespace opf {

struct Estimate {
  std::string object;
  double t = 0.0;
  /// Mean pose and its 6x6 covariance over (x, y, z, yaw, pitch, roll), MRPT's convention.
  mrpt::poses::CPose3DPDFGaussian pose;
  /// trace of the observation covariance used at this step (paper Eq. 11, U = trace(Q~)).
  double observation_trace = 0.0;
  EstimateMode mode = EstimateMode::kMeasured;
};

}  // namespace opf
