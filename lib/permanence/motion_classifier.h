#pragma once
// The dynamics module's first question (paper Sec. III-B.1, Eq. 10-11): was the object moving or
// static over its last H states before the measurement went missing?

#include "opf/core/enum_names.h"
#include "opf/core/option_schema.h"
#include "opf/fit/trajectory_fit.h"

#include <span>

namespace opf {

/// Paper footnote to Eq. 8: T-delta = 0.01 m, R-delta = 0.5 rad (Algorithm 1 prints 0.01 for both;
/// the footnote's values are the ones used in the experiments). The thresholds must exceed the
/// jitter of the estimates, or a still object reads as moving.
enum class MotionTest {
  /// The paper's test (Eq. 10-11): the largest pairwise distance over the window. Noise in the
  /// estimates and the biased centroid of a half-covered object count as motion.
  kMaxPairwise,
  /// The displacement of the robust trajectory fit over the window: what the object did, with
  /// noise and a few biased samples averaged out (Huber). Our option, not the paper's.
  kFittedDisplacement,
};
inline constexpr EnumNames<MotionTest, 2> kMotionTestNames = {
    {{MotionTest::kMaxPairwise, "max_pairwise"},
     {MotionTest::kFittedDisplacement, "fitted_displacement"}}};

struct MotionThresholds {
  double translation = 0.01;  ///< m
  double rotation = 0.5;      ///< rad, geodesic
  MotionTest test = MotionTest::kFittedDisplacement;
};

/// The settings file's `opf.motion_thresholds:` section (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, MotionThresholds& o) {
  v.number("translation", o.translation, non_negative("a distance in m >= 0"));
  v.number("rotation", o.rotation, non_negative("an angle in rad >= 0"));
  v.choice("test", kMotionTestNames, o.test);
}

enum class Motion { kStatic, kMoving };

/// Moving when the largest pairwise translation distance in the window exceeds the translation
/// threshold OR the largest pairwise rotation distance exceeds the rotation threshold. Rotation
/// distance is the geodesic angle (the paper compares Euler-angle vectors, which is not a distance
/// on SO(3) and jumps at +-pi). Fewer than two samples: static (nothing says it moved).
Motion classify_motion(std::span<const TrajectorySample> window,
                       const MotionThresholds& thresholds);

/// The kFittedDisplacement test: moving when the fitted trajectory moves more than the
/// translation threshold, or turns more than the rotation threshold, between the window's first
/// and last times.
Motion classify_fitted_motion(const TrajectoryModel& model, double t_first, double t_last,
                              const MotionThresholds& thresholds);

}  // namespace opf
