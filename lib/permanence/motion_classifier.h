#pragma once
// The dynamics module's first question (paper Sec. III-B.1, Eq. 10-11): was the object moving or
// static over its last H states before the measurement went missing?

#include "fit/trajectory_fit.h"

#include <span>

namespace opf {

/// Paper footnote to Eq. 8: T-delta = 0.01 m, R-delta = 0.5 rad (Algorithm 1 prints 0.01 for both;
/// the footnote's values are the ones used in the experiments). The thresholds must exceed the
/// jitter of the estimates, or a still object reads as moving.
struct MotionThresholds {
  double translation = 0.01;  ///< m
  double rotation = 0.5;      ///< rad, geodesic
};

enum class Motion { kStatic, kMoving };

/// Moving when the largest pairwise translation distance in the window exceeds the translation
/// threshold OR the largest pairwise rotation distance exceeds the rotation threshold. Rotation
/// distance is the geodesic angle (the paper compares Euler-angle vectors, which is not a distance
/// on SO(3) and jumps at +-pi). Fewer than two samples: static (nothing says it moved).
Motion classify_motion(std::span<const TrajectorySample> window,
                       const MotionThresholds& thresholds);

}  // namespace opf
