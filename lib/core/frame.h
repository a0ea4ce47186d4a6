#pragma once
// A Frame: the pose detections of one time instant. Objects absent from it are unobserved.

#include <mrpt/poses/CPose3D.h>
#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

namespace opf {

/// One object's measured 6-DoF pose at a frame's time.
struct Detection {
  std::string object;
  mrpt::poses::CPose3D pose;
  /// m: the noise the detector states for this detection beyond its usual (a partial view's), a
  /// standard deviation per axis of the position; 0: none. Estimators add it in variance to their
  /// configured observation noise (observation_sigma in estimator.h).
  double extra_noise = 0.0;
  /// m: the object's extent across the line of sight as the detector states it, the radius of the
  /// disc of its whole silhouette's area at its depth; 0: not stated. The occluder module takes it
  /// as how much of the view the object covers (place_visibility.h).
  double radius = 0.0;
  /// m: the full extents of the object's bounding box in its own frame, as a detector that knows
  /// the object's model states them; zero: not stated. The occluder module takes the box, turned
  /// by the object's estimated orientation, as its silhouette (place_visibility.h).
  Eigen::Vector3d box = Eigen::Vector3d::Zero();
};

/// The detections that share one timestamp (seconds). An object with no detection is unobserved.
struct Frame {
  double t = 0.0;
  std::vector<Detection> detections;
  /// True for a frame the log has no row at: inserted inside a gap at the log's frame period, so
  /// that every object is estimated there too.
  bool filled = false;

  /// The detection of `object`, or nullptr when the object is unobserved in this frame.
  const Detection* find(std::string_view object) const {
    for (const auto& d : detections)
      if (d.object == object) return &d;
    return nullptr;
  }
};

}  // namespace opf
