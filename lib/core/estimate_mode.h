#pragma once
// What produced an estimate: the word written in the `mode` column of result files.

#include <array>
#include <string_view>

namespace opf {

enum class EstimateMode {
  kMeasured,    ///< updated with a real measurement
  kPredicted,   ///< propagated by the motion model only (measurement missing)
  kDynamics,    ///< OPF: updated with the fitted trajectory's extrapolation (dynamics module)
  kOccluder,    ///< OPF: updated with the occluder's measurement (occluder module)
  kRandomWalk,  ///< occlusion-aware PF: occluded particles random-walk in a widening search
};

/// Every mode, for readers that map a word back to its mode.
inline constexpr std::array<EstimateMode, 5> kEstimateModes = {
    EstimateMode::kMeasured, EstimateMode::kPredicted, EstimateMode::kDynamics,
    EstimateMode::kOccluder, EstimateMode::kRandomWalk};

constexpr std::string_view to_string(EstimateMode mode) {
  switch (mode) {
    case EstimateMode::kMeasured:
      return "measured";
    case EstimateMode::kPredicted:
      return "predicted";
    case EstimateMode::kDynamics:
      return "dynamics";
    case EstimateMode::kOccluder:
      return "occluder";
    case EstimateMode::kRandomWalk:
      return "random_walk";
  }
  return "unknown";
}

}  // namespace opf
