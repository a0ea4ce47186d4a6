#include "opf/permanence/displacement_spread.h"

#include <algorithm>
#include <cmath>

namespace opf {

namespace {
constexpr double kLagTolerance = 0.25;  // share of the lag a pair's own may differ by
}  // namespace

Eigen::Vector3d DisplacementProfile::at(double lag) const {
  if (lags.empty() || !(lag > 0.0)) return Eigen::Vector3d::Zero();
  if (lag <= lags.front()) return mean_squares.front() * (lag / lags.front());
  if (lag >= lags.back()) return mean_squares.back() * (lag / lags.back());
  const auto above = std::upper_bound(lags.begin(), lags.end(), lag);
  const auto k = static_cast<std::size_t>(above - lags.begin());
  const double f = (lag - lags[k - 1]) / (lags[k] - lags[k - 1]);
  return (1.0 - f) * mean_squares[k - 1] + f * mean_squares[k];
}

void DisplacementSpread::add(double t, const Eigen::Vector3d& position) {
  for (std::size_t b = 0; b < kLags.size(); ++b) {
    const double lag = kLags[b];
    const double target = t - lag;
    // The measurement nearest `target`: recent_ is in time order.
    const auto after = std::lower_bound(recent_.begin(), recent_.end(), target,
                                        [](const Sample& s, double x) { return s.t < x; });
    const Sample* nearest = nullptr;
    if (after != recent_.end()) nearest = &*after;
    if (after != recent_.begin()) {
      const Sample& before = *std::prev(after);
      if (!nearest || target - before.t < nearest->t - target) nearest = &before;
    }
    if (!nearest || std::abs(t - nearest->t - lag) > kLagTolerance * lag) continue;
    squares_.col(static_cast<Eigen::Index>(b)) += (position - nearest->position).cwiseAbs2();
    lag_sums_[b] += t - nearest->t;
    ++pairs_[b];
  }
  recent_.push_back({t, position});
  const double keep = (1.0 + kLagTolerance) * kLags.back();
  while (!recent_.empty() && t - recent_.front().t > keep) recent_.pop_front();
}

void DisplacementSpread::clear() {
  recent_.clear();
  squares_.setZero();
  lag_sums_ = {};
  pairs_ = {};
}

DisplacementProfile DisplacementSpread::profile() const {
  DisplacementProfile p;
  for (std::size_t b = 0; b < kLags.size(); ++b) {
    if (pairs_[b] < kMinimumPairs) continue;
    const double n = static_cast<double>(pairs_[b]);
    p.lags.push_back(lag_sums_[b] / n);
    p.mean_squares.push_back(squares_.col(static_cast<Eigen::Index>(b)) / n);
  }
  return p;
}

}  // namespace opf
