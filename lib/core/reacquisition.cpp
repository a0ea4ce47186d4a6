#include "opf/core/reacquisition.h"

#include <limits>

namespace opf {

void Reacquisition::add(const std::string& object, bool measured, double translation_error) {
  tracks_[object].push_back({measured, translation_error});
}

ReacquisitionResult Reacquisition::result(double settled_factor) const {
  double visible_sum = 0.0;
  std::size_t visible = 0;
  for (const auto& [object, frames] : tracks_)
    for (const Frame& f : frames)
      if (f.measured) {
        visible_sum += f.error;
        ++visible;
      }
  ReacquisitionResult r;
  if (visible == 0) {
    r.first_error = r.frames_to_settle = std::numeric_limits<double>::quiet_NaN();
    return r;
  }
  const double settled = settled_factor * visible_sum / static_cast<double>(visible);
  double first_sum = 0.0, frames_sum = 0.0;
  for (const auto& [object, frames] : tracks_) {
    for (std::size_t i = 1; i < frames.size(); ++i) {
      if (!frames[i].measured || frames[i - 1].measured) continue;  // not the end of a gap
      ++r.gaps;
      first_sum += frames[i].error;
      std::size_t k = i;
      while (k < frames.size() && frames[k].measured && frames[k].error > settled) ++k;
      frames_sum += static_cast<double>(k - i);
    }
  }
  if (r.gaps == 0) {
    r.first_error = r.frames_to_settle = std::numeric_limits<double>::quiet_NaN();
    return r;
  }
  r.first_error = first_sum / static_cast<double>(r.gaps);
  r.frames_to_settle = frames_sum / static_cast<double>(r.gaps);
  return r;
}

}  // namespace opf
