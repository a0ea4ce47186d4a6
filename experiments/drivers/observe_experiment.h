#pragma once
// Renders and detects every frame of a scripted experiment once: its truth and what the camera
// saw, the input every seed and estimator of an open-loop run shares.

#include "drivers/experiment_run.h"
#include "opf/sim/camera_model.h"
#include "opf/sim/colour_blob_detector.h"
#include "opf/sim/experiment_config.h"

namespace opf::experiments {

sim::CameraModel camera_of(const sim::ExperimentConfig& config);
/// The detector as the experiment's `measurement` sets it (min_area_pixels).
sim::ColourBlobDetectorOptions detection_of(const sim::ExperimentConfig& config);

/// Throws std::invalid_argument naming the experiment and the object if an object of interest
/// is measured (sim::measured) in none of `camera`'s frames: the run would track and score nothing.
void refuse_unseen_objects(const sim::ExperimentConfig& config,
                           const std::vector<sim::CameraFrame>& camera);

/// Throws that std::invalid_argument for `object`, unseen in `frames` frames.
[[noreturn]] void refuse_unseen_object(const sim::ExperimentConfig& config,
                                       const std::string& object, std::size_t frames);

/// Throws as refuse_unseen_objects does.
Observation observe_experiment(const sim::ExperimentConfig& config, const Progress& progress = {});

}  // namespace opf::experiments
