#include "opf/core/ground_truth.h"

#include "opf/core/closest_name.h"
#include "opf/core/pose_conversion.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace opf {
namespace {

// Twice the median interval between consecutive rows: a row missing now and then is bridged, a
// dropout of several is not. 0 for a single row.
double bridge_of(const std::vector<std::pair<double, mrpt::poses::CPose3D>>& rows) {
  if (rows.size() < 2) return 0.0;
  std::vector<double> intervals;
  intervals.reserve(rows.size() - 1);
  for (std::size_t k = 1; k < rows.size(); ++k)
    intervals.push_back(rows[k].first - rows[k - 1].first);
  const auto middle = intervals.begin() + static_cast<std::ptrdiff_t>(intervals.size() / 2);
  std::nth_element(intervals.begin(), middle, intervals.end());
  return 2.0 * *middle;
}

// The first row at or after t.
template <class Rows>
auto first_at_or_after(const Rows& rows, double t) {
  return std::lower_bound(rows.begin(), rows.end(), t,
                          [](const auto& row, double time) { return row.first < time; });
}

mrpt::poses::CPose3D interpolate(const mrpt::poses::CPose3D& a, const mrpt::poses::CPose3D& b,
                                 double fraction) {
  const Eigen::Vector3d p = translation_of(a) + fraction * (translation_of(b) - translation_of(a));
  return make_pose(p, orientation_of(a).slerp(fraction, orientation_of(b)).normalized());
}

}  // namespace

GroundTruth::GroundTruth(const std::vector<Frame>& frames, double tolerance)
    : tolerance_(tolerance) {
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("GroundTruth: the match tolerance must be finite and >= 0 s");
  for (const Frame& frame : frames)
    for (const Detection& d : frame.detections)
      objects_[d.object].rows.emplace_back(frame.t, d.pose);
  for (auto& [name, s] : objects_) {
    std::stable_sort(s.rows.begin(), s.rows.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    s.bridge = bridge_of(s.rows);
  }
}

const GroundTruth::Series* GroundTruth::series(const std::string& object) const {
  const auto found = objects_.find(object);
  return found == objects_.end() ? nullptr : &found->second;
}

std::optional<mrpt::poses::CPose3D> GroundTruth::at(const std::string& object, double t) const {
  const Series* s = series(object);
  if (!s) return std::nullopt;
  const auto& rows = s->rows;  // an object of the truth has a row at least
  const auto after = first_at_or_after(rows, t);
  if (after != rows.end() && after->first == t) return after->second;  // a row at t: as it is
  if (after != rows.end() && after != rows.begin()) {
    const auto& [t0, pose0] = *std::prev(after);
    const auto& [t1, pose1] = *after;
    if (t1 - t0 <= s->bridge) return interpolate(pose0, pose1, (t - t0) / (t1 - t0));
  }
  // Beyond the span, or in a dropout: the nearest row within the tolerance.
  std::optional<mrpt::poses::CPose3D> best;
  double best_distance = tolerance_;
  for (auto candidate : {after, after == rows.begin() ? after : std::prev(after)}) {
    if (candidate == rows.end()) continue;
    const double distance = std::abs(candidate->first - t);
    if (distance <= best_distance) {
      best = candidate->second;
      best_distance = distance;
    }
  }
  return best;
}

std::string GroundTruth::missing(const std::string& object, double t) const {
  std::ostringstream msg;
  msg << "no ground truth for object '" << object << "' at t = " << t;
  const Series* s = series(object);
  if (!s) {
    std::vector<std::string> names;
    for (const auto& [name, rows] : objects_) names.push_back(name);
    msg << ": the truth has no such object (its objects: ";
    for (std::size_t i = 0; i < names.size(); ++i) msg << (i ? ", " : "") << names[i];
    msg << ")";
    if (const auto closest = closest_name(object, names))
      msg << "; did you mean '" << *closest << "'?";
    return msg.str();
  }
  const auto& rows = s->rows;
  const auto after = first_at_or_after(rows, t);
  if (after != rows.begin() && after != rows.end())
    msg << " (a dropout of the truth: no rows from " << std::prev(after)->first << " to "
        << after->first << " s, further apart than twice its median interval, " << s->bridge / 2
        << " s)";
  else
    msg << " (its rows run from " << rows.front().first << " to " << rows.back().first
        << " s; beyond them a row within " << tolerance_ << " s is taken)";
  return msg.str();
}

}  // namespace opf
