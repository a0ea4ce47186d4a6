#pragma once
// Reacquisition after a gap: how far off an estimator is at the first measured frame after the
// object was hidden, and how many frames it takes to settle again.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace opf {

struct ReacquisitionResult {
  std::size_t gaps = 0;  ///< gaps followed by a measured frame
  /// Mean over those gaps of the translation error at the first measured frame after each, m.
  double first_error = 0.0;
  /// Mean over those gaps of the frames from that frame on until the error is at most
  /// `settled_factor` x the mean error over all measured frames (0: settled at once). A track that
  /// does not settle before the next gap or its end counts the frames it had.
  double frames_to_settle = 0.0;
};

class Reacquisition {
 public:
  /// One frame of one object, in time order per object.
  void add(const std::string& object, bool measured, double translation_error);

  /// NaN means when no gap was followed by a measurement.
  ReacquisitionResult result(double settled_factor = 2.0) const;

 private:
  struct Frame {
    bool measured;
    double error;
  };
  std::map<std::string, std::vector<Frame>> tracks_;
};

}  // namespace opf
