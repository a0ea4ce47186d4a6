#pragma once
// What produced an estimate: the word written in the `mode` column of result files.

#include "opf/core/enum_names.h"

#include <string_view>

namespace opf {

enum class EstimateMode {
  kMeasured,    ///< updated with a real measurement
  kPredicted,   ///< propagated by the motion model only (measurement missing)
  kDynamics,    ///< OPF: updated with the fitted trajectory's extrapolation (dynamics module)
  kCarried,     ///< OPF: carried by its occluder, whose measurement updates it (occluder module)
  kLeft,        ///< OPF: left where its occluder hid it (occluder module), propagated in place
  kRandomWalk,  ///< occlusion-aware PF: occluded particles random-walk in a widening search
};

/// The words of the `mode` column, every mode once.
inline constexpr EnumNames<EstimateMode, 6> kEstimateModeNames = {
    {{EstimateMode::kMeasured, "measured"},
     {EstimateMode::kPredicted, "predicted"},
     {EstimateMode::kDynamics, "dynamics"},
     {EstimateMode::kCarried, "carried"},
     {EstimateMode::kLeft, "left"},
     {EstimateMode::kRandomWalk, "random_walk"}}};

constexpr std::string_view to_string(EstimateMode mode) {
  return name_of(kEstimateModeNames, mode);
}

}  // namespace opf
