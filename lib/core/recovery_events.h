#pragma once
// What an estimator had to do at a step to stay usable, written after the mode word in the `mode`
// column of result files ("measured+reset", "occluder+underflow+capped"), so a user replaying a
// log sees which frames the filter had to rescue rather than track.

#include "opf/core/estimate_mode.h"

#include <optional>
#include <string>
#include <string_view>

namespace opf {

struct RecoveryEvents {
  /// "reset": no particle of a portion lay within reset_gate sigmas of a real measurement (a
  /// teleported object, a wrong detection, an object revealed far from where it was believed),
  /// so that portion was scattered around the measurement (sensor resetting).
  bool sensor_reset = false;
  /// "underflow": the measurement's likelihood under every particle of a portion fell below the
  /// smallest normal double (a wild measurement with sensor resetting off, or a virtual
  /// measurement far from the cloud). The log-domain weights kept their ratios; if not one weight
  /// was finite they were reset to uniform. Either way the estimate stays finite.
  bool weights_underflow = false;
  /// "capped": the OPF's Q~ reached its cap (UncertaintyOptions::max_scale) and no longer grows
  /// with the time hidden, so trace(Q~) stays finite through an occlusion of any length.
  bool trace_capped = false;
  /// "filled": the log has no row at this frame; it was inserted inside a gap at the log's frame
  /// period (Frame::filled), so the estimate is a prediction through the gap.
  bool frame_filled = false;

  bool any() const { return sensor_reset || weights_underflow || trace_capped || frame_filled; }
  friend bool operator==(const RecoveryEvents&, const RecoveryEvents&) = default;
};

/// The mode column's text: the mode word, then "+reset", "+underflow", "+capped" and "+filled" in
/// that order for each event that occurred.
std::string mode_column(EstimateMode mode, const RecoveryEvents& events);

/// What a mode column says, or nullopt when it is not a mode word followed by known events.
struct ModeColumn {
  EstimateMode mode = EstimateMode::kMeasured;
  RecoveryEvents events;
};
std::optional<ModeColumn> parse_mode_column(std::string_view text);

}  // namespace opf
