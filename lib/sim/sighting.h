#pragma once
// What the simulated camera saw of one tracked body in one frame, before sensor noise: the
// experiments render and detect once, then draw seeded noise per run, so every seed and estimator
// sees the same images.

#include <Eigen/Core>

#include <string>
#include <vector>

namespace opf::sim {

struct Sighting {
  std::string object;
  /// Detected blob area over the body's unoccluded silhouette area; 0 when no blob was found.
  double visible_fraction = 0.0;
  bool detected = false;  ///< a blob above the minimum area was found
  /// The body's centre as the camera measures it: the blob centroid back-projected onto the
  /// visible surface, pushed back along the viewing ray by the body's known half-depth. A partly
  /// covered body's centroid is biased towards its visible part, as with a real detector.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// m: how far a partial view can have moved `position` from the centre, (1 - f) rho for the
  /// visible fraction f and the silhouette's equivalent-disc radius rho at the body's depth
  /// (camera_sensor.h); 0 for a body seen whole.
  double partial_view_offset = 0.0;
  /// m: the radius rho of the disc of the body's whole silhouette's area at its depth, as a
  /// detector that knows the object's model states it; 0 when no blob was found.
  double radius = 0.0;
  /// m: the body's bounding box (a box body's own size), full extents in its frame, as a
  /// detector that knows the object's model states it; zero for other shapes and when no blob
  /// was found.
  Eigen::Vector3d box = Eigen::Vector3d::Zero();
};

/// One frame's sightings of every tracked body.
struct CameraFrame {
  double t = 0.0;
  std::vector<Sighting> sightings;
};

}  // namespace opf::sim
