#include "opf/core/hidden_error_profile.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace opf {

void HiddenErrorProfile::add(double time_hidden, double translation_error, double rotation_error) {
  if (!(time_hidden > 0.0) || !std::isfinite(time_hidden))
    throw std::invalid_argument("HiddenErrorProfile: time hidden must be positive and finite");
  // The 1e-9 keeps a frame at exactly k bin widths (30 Hz: 3 periods = 0.1 s) in bin k - 1.
  const double upper = std::max(1.0, std::ceil(time_hidden / kBinWidth - 1e-9));
  const auto bin = static_cast<std::size_t>(upper) - 1;
  if (bin >= sums_.size()) sums_.resize(bin + 1);
  HiddenErrorBin& b = sums_[bin];
  ++b.frames;
  b.translation += translation_error;
  b.rotation += rotation_error;
}

std::vector<HiddenErrorBin> HiddenErrorProfile::means() const {
  std::vector<HiddenErrorBin> bins = sums_;
  for (HiddenErrorBin& b : bins) {
    if (b.frames == 0) continue;
    b.translation /= static_cast<double>(b.frames);
    b.rotation /= static_cast<double>(b.frames);
  }
  return bins;
}

}  // namespace opf
