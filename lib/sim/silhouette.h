#pragma once
// The image area a body would cover if nothing hid it, so that experiments can tell how much of
// a detected object is visible (visible fraction = detected area / expected area).

#include "opf/sim/body.h"
#include "opf/sim/camera_model.h"

namespace opf::sim {

/// Area in pixels of the convex hull of the body's projected outline, the whole of it, past the
/// image's edges too: the frame's edge covers a body as another body would (one half out of the
/// frame is seen in part, visible fraction a half, and states its whole size). Exact up to
/// sampling for the convex shapes of body.h: a box projects its 8 corners, a cylinder 2 x 256
/// points on its cap rims, a sphere 720 points on its contour generator (the circle where the
/// viewing cone touches it), so the error is below 0.01%. The renderer draws spheres and cylinders
/// as inscribed polyhedra, slightly smaller (see SceneRendererOptions). Returns 0 for a body wholly
/// behind the camera, NaN for one that straddles the camera plane (its projection is unbounded) or
/// contains the camera.
double expected_silhouette_area(const Body& body, const BodyPose& pose, const CameraModel& camera);

}  // namespace opf::sim
