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
                          kIntervalTolerance * std::max(interval, last_interval_))
      differences_.push_back(
          {t, (step - *last_step_).cwiseAbs2(), (turn - *last_turn_).cwiseAbs2()});
    last_step_ = step;
    last_turn_ = turn;
    last_interval_ = interval;
  }
  last_t_ = t;
  last_position_ = position;
  last_orientation_ = q;
  while (!differences_.empty() && t - differences_.front().t > window_) differences_.pop_front();
}

void DetectorJitter::clear() {
  differences_.clear();
  last_t_.reset();
  last_step_.reset();
  last_turn_.reset();
}

Eigen::Vector3d DetectorJitter::sigmas(Eigen::Vector3d Difference::*squares) {
  Eigen::Vector3d sigma;
  for (int axis = 0; axis < 3; ++axis) {
    scratch_.clear();
    for (const Difference& d : differences_) scratch_.push_back((d.*squares)(axis));
    sigma(axis) = std::sqrt(noise_variance_from_second_differences(scratch_));
  }
  return sigma;
}

std::optional<double> DetectorJitter::rotation_sigma() {
  if (differences_.size() < kMinimumDifferences) return std::nullopt;
  return sigmas(&Difference::rotation_squares).maxCoeff();
}

std::optional<Eigen::Vector3d> DetectorJitter::translation_sigmas() {
  if (differences_.size() < kMinimumDifferences) return std::nullopt;
  return sigmas(&Difference::translation_squares);
}

}  // namespace opf
