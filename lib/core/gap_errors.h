#pragma once
// The errors per gap: each stretch of frames in which the log has no detection of an object, from
// the first frame without it to the last. The gaps are the log's, the same for every estimator and
// seed, so two estimators compare occlusion by occlusion; a mean over all hidden frames hides
// which gaps an estimator loses.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace opf {

struct GapError {
  std::string object;
  double start = 0.0;  ///< s, the first frame without the object's detection
  double end = 0.0;    ///< s, the last
  std::size_t frames = 0;
  double translation = 0.0;  ///< m, the sum over the gap's scored frames
  double rotation = 0.0;     ///< geodesic rad, likewise
};

class GapErrors {
 public:
  /// One scored estimate at t, in time order per object; `detected`: the log has the object's
  /// detection in this frame (a frame with one ends the object's gap).
  void add(const std::string& object, double t, bool detected, double translation_error,
           double rotation_error);

  /// Every gap so far, an open one included, in the order they began (error sums, not means).
  const std::vector<GapError>& gaps() const { return gaps_; }

 private:
  std::vector<GapError> gaps_;
  std::map<std::string, std::size_t> open_;  ///< per object in a gap: its index in gaps_
};

}  // namespace opf
