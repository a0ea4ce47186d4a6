#include "opf/core/gap_errors.h"

namespace opf {

void GapErrors::add(const std::string& object, double t, bool detected, double translation_error,
                    double rotation_error) {
  if (detected) {
    open_.erase(object);
    return;
  }
  auto open = open_.find(object);
  if (open == open_.end()) {
    open = open_.emplace(object, gaps_.size()).first;
    gaps_.push_back({object, t, t, 0, 0.0, 0.0});
  }
  GapError& gap = gaps_[open->second];
  gap.end = t;
  ++gap.frames;
  gap.translation += translation_error;
  gap.rotation += rotation_error;
}

}  // namespace opf
