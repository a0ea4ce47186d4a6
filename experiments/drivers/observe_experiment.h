#pragma once
// Renders and detects every frame of a scripted experiment once: its truth and what the camera
// saw, the input every seed and estimator of an open-loop run shares.

#include "drivers/experiment_run.h"
#include "opf/sim/camera_model.h"
#include "opf/sim/experiment_config.h"

namespace opf::experiments {

sim::CameraModel camera_of(const sim::ExperimentConfig& config);

Observation observe_experiment(const sim::ExperimentConfig& config, const Progress& progress = {});

}  // namespace opf::experiments
