#pragma once
// Turns a frame's noiseless sightings into the measurements an estimator sees (paper Sec. IV-B):
// a position from the colour blob with seeded noise, and an orientation from a marker-style
// sensor (the true orientation with seeded noise), for every body seen well enough.

#include "opf/core/frame.h"
#include "opf/core/random.h"
#include "opf/sim/body.h"
#include "opf/sim/experiment_config.h"
#include "opf/sim/sighting.h"

namespace opf::sim {

/// Whether a sighting becomes a measurement: detected, and visible at least
/// settings.min_visible_fraction.
inline bool measured(const Sighting& s, const MeasurementSettings& settings) {
  return s.detected && s.visible_fraction >= settings.min_visible_fraction;
}

/// Bodies whose sighting is undetected, or visible below settings.min_visible_fraction, are
/// unobserved (absent from the frame). A partly covered body's detection states its partial view
/// (Sighting::partial_view_offset) as its extra noise (Detection::extra_noise), and every detection
/// its silhouette's radius and box (Sighting::radius, ::box) unless settings.state_sizes is off.
/// Draws the same number of random numbers for every body and frame, seen or not, so one body's
/// visibility never shifts another's noise.
Frame noisy_measurement(const CameraFrame& camera, const SceneSnapshot& truth,
                        const MeasurementSettings& settings, Random& noise);

}  // namespace opf::sim
