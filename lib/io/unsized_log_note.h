#pragma once
// A note for a log whose detector states no object sizes, once the OPF's occluder module has
// taken a hidden object (carried or left): without sizes the module weighs each candidate cover by
// a reach it does not know and judges a place hidden by where the cover last let it be seen,
// which tells carried from left less often than stated sizes do (docs/results.md, the hand scenes
// with --unsized). The note names the columns that state them. `opf track` and `opf evaluate`
// print it, the Python module's track_log gives it as a warning.

#include "opf/core/estimate.h"
#include "opf/core/frame.h"

#include <string>

namespace opf {

class UnsizedLogWatch {
 public:
  void saw(const Detection& detection) {
    size_stated_ = size_stated_ || detection.radius > 0.0 || detection.box.any();
  }
  void saw(const Estimate& estimate) {
    occluder_took_ = occluder_took_ || estimate.mode == EstimateMode::kCarried ||
                     estimate.mode == EstimateMode::kLeft;
  }
  /// Whether the occluder module took an object and no detection stated a size.
  bool note_due() const { return occluder_took_ && !size_stated_; }

 private:
  bool size_stated_ = false;
  bool occluder_took_ = false;
};

/// The note: one sentence, without its sender's name or a line end.
std::string unsized_log_note();

}  // namespace opf
