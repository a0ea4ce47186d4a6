#pragma once
// A hidden object's particles follow the motion-model banks' predictive mixture
// (motion_model_bank.h, rotation_model_bank.h), as a multiple-model particle filter's do. At the
// onset of a gap every translation particle draws a member per world axis, and every rotation
// particle a rotation member, each with its probability at the last measurement. Over a step
// from horizon h0 to h1 (s after that measurement) a particle of member j moves by the member's
// predicted mean motion and spreads by the growth of its predicted variance:
//
//   x <- x + m_j(h1) - m_j(h0) + e,   e ~ N(0, P_j(h1) - P_j(h0)),
//
// so that at any horizon h the cloud is sum_j w_j N(m_j(h) - m_j(0), P_j(h) - P_j(0)) added to
// the cloud the measurement left: the prediction, with no scale factor or floor. A rotation
// particle turns by its member's world-frame turn R_j(h1) R_j(h0)^T and spreads isotropically by
// sqrt(tr(C_j(h1) - C_j(h0)) / 3) per tangent axis. No particle is reweighted while this runs,
// so each keeps its member.

#include "opf/core/random.h"
#include "opf/particles/gaussian_sampler.h"
#include "opf/particles/pose_particle_filter.h"
#include "opf/permanence/motion_model_bank.h"
#include "opf/permanence/rotation_model_bank.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace opf {

class MixtureParticleMotion {
 public:
  explicit MixtureParticleMotion(std::uint64_t seed);

  /// Draws every particle's member from the banks' probabilities (both banks initialised), and
  /// reorders the rotation particles so that each member's are consecutive.
  void start(const MotionModelBank& translation, const RotationModelBank& rotation,
             PoseParticleFilter& filter);
  /// Moves the particles from horizon h0 to h1 >= h0 (s after the banks' last update). The
  /// members' predictions at h1 are kept for the next step, whose h0 it is.
  void advance(const MotionModelBank& translation, const RotationModelBank& rotation, double h0,
               double h1, PoseParticleFilter& filter);

  /// The trace of the mixture's covariance at the last horizon advanced to, less its trace at 0
  /// (m^2 + rad^2): the uncertainty the prediction added to the cloud's.
  double added_trace() const;
  /// The most probable model per axis, then the rotation's, e.g.
  /// "constant_velocity,constant_velocity,ballistic/constant_angular_velocity".
  static std::string label(const MotionModelBank& translation, const RotationModelBank& rotation);

 private:
  /// Every member's prediction at one horizon, with its weight (fixed while hidden).
  struct Predictions {
    double horizon = -1.0;
    BankPrediction translation;
    std::vector<RotationMemberPrediction> rotation;
  };
  static void predict(const MotionModelBank& translation, const RotationModelBank& rotation,
                      double horizon, Predictions& out);
  /// trace of the mixture's covariance (translation by the law of total variance; rotation by
  /// the members' traces).
  static double mixture_trace(const Predictions& p);
  void move_translation(const Predictions& from, const Predictions& to,
                        TranslationParticles& particles);
  void move_rotation(const Predictions& from, const Predictions& to, RotationParticles& particles);
  void group_by_member(const RotationModelBank& rotation, RotationParticles& particles);

  Random random_;          ///< the members' draws
  GaussianSampler noise_;  ///< the spread, in bulk
  std::array<std::vector<std::uint8_t>, 3> translation_members_;
  std::vector<std::size_t> rotation_ends_;  ///< member k's rotation particles end before ends[k]
  Predictions last_;                        ///< at the last horizon reached
  Predictions next_;
  double trace_at_onset_ = 0.0;
  std::vector<double> shift_, spread_;  ///< per member, for one step
  std::vector<Eigen::Quaterniond> turn_;
};

}  // namespace opf
