#pragma once
// The image area a body would cover if nothing hid it, so that experiments can tell how much of
// a detected object is visible (visible fraction = detected area / expected area).

#include "opf/sim/body.h"
#include "opf/sim/camera_model.h"

namespace opf::sim {

/// Area in pixels of the convex hull of the body's projected outline, clipped to the image
/// rectangle [-0.5, width - 0.5] x [-0.5, height - 0.5] (so a body half out of the frame expects
/// half its area, as the detector can only see that half). Exact up to sampling for the convex
/// shapes of body.h: a box projects its 8 corners, a cylinder 2 x 256 points on its cap rims, a
/// sphere 720 points on its contour generator (the circle where the viewing cone touches it),
/// so the error is below 0.01%. The renderer draws spheres and cylinders as inscribed polyhedra,
/// slightly smaller (see SceneRendererOptions).
/// Returns 0 for a body wholly behind the camera, NaN for one that straddles the camera plane
/// (its projection is unbounded) or contains the camera.
double expected_silhouette_area(const Body& body, const BodyPose& pose, const CameraModel& camera);

}  // namespace opf::sim
