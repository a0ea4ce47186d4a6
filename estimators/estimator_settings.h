#pragma once
// Every estimator's options in one place: what a YAML config file sets and the registry reads.

#include "estimators/cv_kalman_options.h"
#include "particles/particle_filter_options.h"

namespace opf {

struct EstimatorSettings {
  PoseParticleFilterOptions pf;  ///< standard PF (and, later, the particle part of the OPF)
  CvKalmanOptions cvkf;
};

}  // namespace opf
