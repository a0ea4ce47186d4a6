#pragma once
// The ground truth an evaluation scores estimates against: every object's poses in time order, at
// the truth's own times. An estimate at time t takes the truth interpolated between the two rows
// around t (position linearly, orientation by slerp), so a motion-capture truth at its own rate
// scores a detector's log at another, and a frame filled inside a gap is scored where the truth
// runs on. Two rows further apart than twice the object's median row interval are a dropout of the
// truth, not bridged; beyond its first or last row, a row within the match tolerance serves.

#include "opf/core/frame.h"

#include <mrpt/poses/CPose3D.h>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace opf {

class GroundTruth {
 public:
  /// `frames`: the truth's frames in time order. `tolerance` (s, >= 0): how far from a row an
  /// estimate beyond the truth's span still takes that row. std::invalid_argument otherwise.
  GroundTruth(const std::vector<Frame>& frames, double tolerance);

  /// The truth of `object` at t; none where the truth does not reach t (see above).
  std::optional<mrpt::poses::CPose3D> at(const std::string& object, double t) const;

  /// Why at(object, t) has nothing: the object is missing from the truth (its objects named,
  /// with a near miss), or its rows do not reach that time (their span, or the dropout, given).
  std::string missing(const std::string& object, double t) const;

 private:
  struct Series {
    std::vector<std::pair<double, mrpt::poses::CPose3D>> rows;
    double bridge = 0.0;  ///< s: the farthest apart two rows are interpolated between
  };
  const Series* series(const std::string& object) const;

  double tolerance_;
  std::map<std::string, Series> objects_;
};

}  // namespace opf
