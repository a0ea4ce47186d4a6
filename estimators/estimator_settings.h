#pragma once
// Every estimator's options in one place: what a YAML config file sets and the registry reads.

#include "opf/estimators/cv_kalman_options.h"
#include "opf/estimators/imm_options.h"
#include "opf/estimators/oapf_options.h"
#include "opf/estimators/opf_options.h"
#include "opf/particles/particle_filter_options.h"

namespace opf {

struct EstimatorSettings {
  /// The particle filter every particle estimator runs on: the standard PF itself, and the
  /// particle part of the OPF and of the occlusion-aware PF. The registry copies it over
  /// opf.particles and oapf.particles, so the three are always compared on the same filter.
  PoseParticleFilterOptions pf;
  CvKalmanOptions cvkf;
  ImmOptions imm;                ///< interacting-multiple-model Kalman baseline
  OpfOptions opf;                ///< the Object Permanence update's modules
  OcclusionAwarePfOptions oapf;  ///< random-walk occlusion-aware PF baseline
};

/// The settings file (experiments/configs/estimators.yaml documents it with the defaults): its
/// sections in the order `opf config --dump` writes them (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, EstimatorSettings& s) {
  v.section("pf", [&] { describe_options(v, s.pf); });
  v.section("cvkf", [&] { describe_options(v, s.cvkf); });
  v.section("imm", [&] { describe_options(v, s.imm); });
  v.section("opf", [&] { describe_options(v, s.opf); });
  v.section("oapf", [&] { describe_options(v, s.oapf); });
}

}  // namespace opf
