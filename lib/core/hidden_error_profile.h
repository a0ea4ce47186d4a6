#pragma once
// Error against time hidden: the errors of the frames without a measurement, binned by the time
// since the object's last measurement (0.1 s bins). It shows how fast each estimator's
// extrapolation degrades, which a mean over a gap hides.

#include <cstddef>
#include <vector>

namespace opf {

struct HiddenErrorBin {
  std::size_t frames = 0;
  double translation = 0.0;  ///< m, sum over the bin's frames (mean after result())
  double rotation = 0.0;     ///< geodesic rad, likewise
};

class HiddenErrorProfile {
 public:
  static constexpr double kBinWidth = 0.1;  ///< s

  /// A hidden frame `time_hidden` s after the object's last measurement (> 0).
  void add(double time_hidden, double translation_error, double rotation_error);

  /// Bin k covers time hidden in (k kBinWidth, (k + 1) kBinWidth]: a frame one period after the
  /// last measurement is in bin 0. Means per bin; empty bins have frames = 0 and means 0.
  std::vector<HiddenErrorBin> means() const;

 private:
  std::vector<HiddenErrorBin> sums_;
};

}  // namespace opf
