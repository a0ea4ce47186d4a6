#pragma once
// A run's measurements as files other trackers and `opf track` / `opf evaluate` read: each seed's
// detections as a measurement log, and the scene's truth as one more.

#include "drivers/experiment_run.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace opf::experiments {

/// Writes <out>/<experiment>_measurements_seed<K>.csv for each seed index K of the run
/// (first_seed .. first_seed + seeds - 1): every detection of measurement_stream, with the extra
/// noise, radius and box the detector states where any detection states them; and
/// <out>/<experiment>_truth.csv: every tracked body's true pose at every frame. Returns the
/// files, truth last.
std::vector<std::filesystem::path> write_measurement_logs(const std::filesystem::path& out,
                                                          const sim::ExperimentConfig& config,
                                                          const Observation& observation,
                                                          std::uint64_t base_seed,
                                                          std::size_t first_seed,
                                                          std::size_t seeds);

}  // namespace opf::experiments
