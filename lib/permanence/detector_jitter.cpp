#include "opf/permanence/detector_jitter.h"

#include "opf/core/so3.h"

#include <algorithm>
#include <cmath>

namespace opf {
namespace {

// Intervals within this share of each other count as equal (a camera's frame times jitter; a
// missed frame doubles the interval).
constexpr double kIntervalTolerance = 0.25;

// The median of chi-square with one degree of freedom.
constexpr double kChiSquareOneMedian = 0.4549;

}  // namespace

void DetectorJitter::add(double t, const Eigen::Quaterniond& orientation) {
  const Eigen::Quaterniond q = orientation.normalized();
  if (last_t_) {
    const double interval = t - *last_t_;
    const Eigen::Vector3d turn = so3::difference(last_orientation_, q);
    if (last_turn_ && std::abs(interval - last_interval_) <=
                          kIntervalTolerance * std::max(interval, last_interval_)) {
      const Difference d{t, (turn - *last_turn_).cwiseAbs2()};
      // A non-finite difference (a measurement with NaN) says nothing of the noise, and would
      // break the axes' order.
      if (d.squares.allFinite()) {
        differences_.push_back(d);
        insert(d);
      }
    }
    last_turn_ = turn;
    last_interval_ = interval;
  }
  last_t_ = t;
  last_orientation_ = q;
  while (!differences_.empty() && t - differences_.front().t > window_) {
    erase(differences_.front());
    differences_.pop_front();
  }
}

void DetectorJitter::insert(const Difference& d) {
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double>& sorted = sorted_[static_cast<std::size_t>(axis)];
    sorted.insert(std::upper_bound(sorted.begin(), sorted.end(), d.squares(axis)), d.squares(axis));
  }
}

void DetectorJitter::erase(const Difference& d) {
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double>& sorted = sorted_[static_cast<std::size_t>(axis)];
    // The very value inserted is there: equal copies are interchangeable.
    sorted.erase(std::lower_bound(sorted.begin(), sorted.end(), d.squares(axis)));
  }
}

void DetectorJitter::clear() {
  differences_.clear();
  for (std::vector<double>& sorted : sorted_) sorted.clear();
  last_t_.reset();
  last_turn_.reset();
}

std::optional<double> DetectorJitter::rotation_sigma() const {
  if (differences_.size() < kMinimumDifferences) return std::nullopt;
  double largest = 0.0;
  for (const std::vector<double>& sorted : sorted_)
    largest = std::max(largest, sorted[sorted.size() / 2]);  // the median square
  return std::sqrt(largest / (6.0 * kChiSquareOneMedian));
}

}  // namespace opf
