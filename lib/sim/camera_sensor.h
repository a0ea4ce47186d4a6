#pragma once
// The simulated camera of the paper's experiments (Sec. IV-B): renders the scene, finds each
// tracked body's colour blob, and reports its centre and how much of it is visible.

#include "opf/sim/camera_model.h"
#include "opf/sim/colour_blob_detector.h"
#include "opf/sim/scene_renderer.h"
#include "opf/sim/sighting.h"

namespace opf::sim {

class CameraSensor {
 public:
  /// Creates the renderer (see SceneRenderer: one per process at a time).
  CameraSensor(const CameraModel& camera, const SceneRendererOptions& render = {},
               const ColourBlobDetectorOptions& detect = {});

  /// One sighting per tracked body, in the snapshot's order.
  CameraFrame observe(const SceneSnapshot& scene);

  /// The images of the last observe().
  const RgbdFrame& last_image() const { return image_; }
  const CameraModel& camera() const { return camera_; }

 private:
  CameraModel camera_;
  SceneRenderer renderer_;
  ColourBlobDetector detector_;
  RgbdFrame image_;
};

/// How far behind its visible surface a body's centre lies in z-depth when seen whole: the
/// median depth of a sphere's visible cap is r / sqrt(2) in front of its centre (the height
/// sqrt(1 - rho^2) r at the median of rho^2, uniform over the projected disc); a box or cylinder
/// shows the face most directly facing the camera nearest, half its extent from the centre (its
/// side faces, seen obliquely, bias the centroid: see the camera sensor's tests).
/// Tracking known objects, a detector adds this to the blob's depth to measure the centre.
double centre_depth_offset(const Body& body, const BodyPose& pose, const CameraModel& camera);

/// m: how far from a body's centre the centroid of its visible part can lie, for a visible share
/// `visible_fraction` of a silhouette of `expected_area_px` pixels at z-depth `depth` (m): the
/// silhouette taken as the disc of its area, radius rho, a straight edge covering all but a share
/// f of a disc leaves the visible part's centroid within (1 - f) rho of the disc's centre (a half
/// disc's lies 4 rho / (3 pi) = 0.42 rho off, a tenth's 0.82 rho). 0 for a body seen whole.
double partial_view_offset(double visible_fraction, double expected_area_px, double depth,
                           const CameraModel& camera);

/// m: rho, the radius of the disc of a silhouette's area `expected_area_px` (pixels) at z-depth
/// `depth` (m); 0 for no area.
double silhouette_radius(double expected_area_px, double depth, const CameraModel& camera);

}  // namespace opf::sim
