#include "opf/permanence/detector_jitter.h"

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

void DetectorJitter::add(double t, const Eigen::Vector3d& position,
                         const Eigen::Quaterniond& orientation) {
  const Eigen::Quaterniond q = orientation.normalized();
  if (last_t_) {
    const double interval = t - *last_t_;
    const Eigen::Vector3d step = position - last_position_;
    const Eigen::Vector3d turn = so3::difference(last_orientation_, q);
    if (last_turn_ && std::abs(interval - last_interval_) <=
                          kIntervalTolerance * std::max(interval, last_interval_)) {
      const Difference d{t, (step - *last_step_).cwiseAbs2(), (turn - *last_turn_).cwiseAbs2()};
      // A non-finite difference (a measurement with NaN) says nothing of the noise, and would
      // break the channels' order.
      if (d.translation_squares.allFinite() && d.rotation_squares.allFinite()) {
        differences_.push_back(d);
        insert(d);
      }
    }
    last_step_ = step;
    last_turn_ = turn;
    last_interval_ = interval;
  }
  last_t_ = t;
  last_position_ = position;
  last_orientation_ = q;
  while (!differences_.empty() && t - differences_.front().t > window_) {
    erase(differences_.front());
    differences_.pop_front();
  }
}

double DetectorJitter::Difference::square(int channel) const {
  return channel < 3 ? translation_squares(channel) : rotation_squares(channel - 3);
}

void DetectorJitter::insert(const Difference& d) {
  for (int c = 0; c < kChannels; ++c) {
    std::vector<double>& sorted = sorted_[static_cast<std::size_t>(c)];
    const double value = d.square(c);
    sorted.insert(std::upper_bound(sorted.begin(), sorted.end(), value), value);
  }
}

void DetectorJitter::erase(const Difference& d) {
  for (int c = 0; c < kChannels; ++c) {
    std::vector<double>& sorted = sorted_[static_cast<std::size_t>(c)];
    // The very value inserted is there: equal copies are interchangeable.
    sorted.erase(std::lower_bound(sorted.begin(), sorted.end(), d.square(c)));
  }
}

void DetectorJitter::clear() {
  differences_.clear();
  for (std::vector<double>& sorted : sorted_) sorted.clear();
  last_t_.reset();
  last_step_.reset();
  last_turn_.reset();
}

Eigen::Vector3d DetectorJitter::sigmas(int first_channel) const {
  Eigen::Vector3d sigma;
  for (int axis = 0; axis < 3; ++axis)
    sigma(axis) = std::sqrt(noise_variance_from_sorted_squares(
        sorted_[static_cast<std::size_t>(first_channel + axis)]));
  return sigma;
}

std::optional<double> DetectorJitter::rotation_sigma() const {
  if (differences_.size() < kMinimumDifferences) return std::nullopt;
  return sigmas(3).maxCoeff();
}

std::optional<Eigen::Vector3d> DetectorJitter::translation_sigmas() const {
  if (differences_.size() < kMinimumDifferences) return std::nullopt;
  return sigmas(0);
}

}  // namespace opf
