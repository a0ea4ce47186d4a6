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

void DetectorJitter::add(double t, const Eigen::Vector3d& position,
                         const Eigen::Quaterniond& orientation) {
  const Eigen::Quaterniond q = orientation.normalized();
  if (last_t_) {
    const double interval = t - *last_t_;
    Eigen::Matrix<double, kAxes, 1> increment;
    increment << so3::difference(last_orientation_, q), position - last_position_;
    if (last_increment_ && std::abs(interval - last_interval_) <=
                               kIntervalTolerance * std::max(interval, last_interval_)) {
      const Difference d{t, (increment - *last_increment_).cwiseAbs2()};
      // A non-finite difference (a measurement with NaN) says nothing of the noise, and would
      // break the axes' order.
      if (d.squares.allFinite()) {
        differences_.push_back(d);
        insert(d);
      }
    }
    last_increment_ = increment;
    last_interval_ = interval;
  }
  last_t_ = t;
  last_orientation_ = q;
  last_position_ = position;
  while (!differences_.empty() && t - differences_.front().t > window_) {
    erase(differences_.front());
    differences_.pop_front();
  }
}

void DetectorJitter::insert(const Difference& d) {
  for (std::size_t axis = 0; axis < kAxes; ++axis) {
    std::vector<double>& sorted = sorted_[axis];
    const double square = d.squares(static_cast<Eigen::Index>(axis));
    sorted.insert(std::upper_bound(sorted.begin(), sorted.end(), square), square);
  }
}

void DetectorJitter::erase(const Difference& d) {
  for (std::size_t axis = 0; axis < kAxes; ++axis) {
    std::vector<double>& sorted = sorted_[axis];
    // The very value inserted is there: equal copies are interchangeable.
    sorted.erase(
        std::lower_bound(sorted.begin(), sorted.end(), d.squares(static_cast<Eigen::Index>(axis))));
  }
}

void DetectorJitter::clear() {
  differences_.clear();
  for (std::vector<double>& sorted : sorted_) sorted.clear();
  last_t_.reset();
  last_increment_.reset();
}

std::optional<double> DetectorJitter::rotation_sigma() const {
  return sigma(0);
}

std::optional<double> DetectorJitter::translation_sigma() const {
  return sigma(3);
}

std::optional<double> DetectorJitter::sigma(std::size_t first_axis) const {
  if (differences_.size() < kMinimumDifferences) return std::nullopt;
  double largest = 0.0;
  for (std::size_t axis = first_axis; axis < first_axis + 3; ++axis)
    largest = std::max(largest, sorted_[axis][sorted_[axis].size() / 2]);  // the median square
  return std::sqrt(largest / (6.0 * kChiSquareOneMedian));
}

}  // namespace opf
