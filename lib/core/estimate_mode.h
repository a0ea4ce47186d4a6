#pragma once
// What produced an estimate: the word written in the `mode` column of result files.

#include <string_view>

namespace opf {

enum class EstimateMode {
  kMeasured,   ///< updated with a real measurement
  kPredicted,  ///< propagated by the motion model only (measurement missing)
};

constexpr std::string_view to_string(EstimateMode mode) {
  switch (mode) {
    case EstimateMode::kMeasured:
      return "measured";
    case EstimateMode::kPredicted:
      return "predicted";
  }
  return "unknown";
}

}  // namespace opf
