#include "opf/permanence/rotation_jitter.h"

#include "opf/core/so3.h"
#include "opf/permanence/second_difference_noise.h"

#include <algorithm>
#include <cmath>

namespace opf {
namespace {

// Intervals within this share of each other count as equal (a camera's frame times jitter; a
// missed frame doubles the interval).
constexpr double kIntervalTolerance = 0.25;

}  // namespace

void RotationJitter::add(double t, const Eigen::Quaterniond& measured) {
  const Eigen::Quaterniond q = measured.normalized();
  if (last_t_) {
    const double interval = t - *last_t_;
    const Eigen::Vector3d increment = so3::difference(last_orientation_, q);
    if (last_increment_ && std::abs(interval - last_interval_) <=
                               kIntervalTolerance * std::max(interval, last_interval_))
      differences_.push_back({t, (increment - *last_increment_).cwiseAbs2()});
    last_increment_ = increment;
    last_interval_ = interval;
  }
  last_t_ = t;
  last_orientation_ = q;
  while (!differences_.empty() && t - differences_.front().t > window_) differences_.pop_front();
}

void RotationJitter::clear() {
  differences_.clear();
  last_t_.reset();
  last_increment_.reset();
}

std::optional<double> RotationJitter::sigma() {
  if (differences_.size() < kMinimumDifferences) return std::nullopt;
  double largest = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    scratch_.clear();
    for (const Difference& d : differences_) scratch_.push_back(d.squares(axis));
    largest = std::max(largest, noise_variance_from_second_differences(scratch_));
  }
  return std::sqrt(largest);
}

}  // namespace opf
