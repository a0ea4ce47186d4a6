#pragma once
// How far an object has moved in a given time over its whole track: per world axis, the mean
// squared displacement between two of its measurements that far apart (the structure function of
// its motion). Beyond the horizon its motion model was validated to, a prediction that coasts to
// a stop is holding still, and holding still is off by what the object's own past says it moves
// in that time: a hand that swept 10 cm in half a second before may do it again unseen. The
// models' error growth, fitted on errors made at most that horizon ahead, cannot say so.

#include <Eigen/Core>

#include <array>
#include <deque>
#include <vector>

namespace opf {

/// Mean squared displacements at a few lags, for reading at any lag.
struct DisplacementProfile {
  std::vector<double> lags;                   ///< s, increasing: each the mean lag of its pairs
  std::vector<Eigen::Vector3d> mean_squares;  ///< m^2 per world axis, one per lag

  bool empty() const { return lags.empty(); }
  /// At `lag` s: linear between the lags held; below the shortest, in proportion to the lag from
  /// zero; beyond the longest, growing in proportion to the lag (a random walk: a bounded motion
  /// grows slower, a steady one faster, and the track has not shown which). Zero when empty.
  Eigen::Vector3d at(double lag) const;
};

/// Pairs every measurement with the one nearest each lag before it (0.125, 0.25, ... 4 s, within
/// a quarter of the lag), gaps or not: two measurements either side of a gap show how far the
/// object moved while hidden.
class DisplacementSpread {
 public:
  void add(double t, const Eigen::Vector3d& position);
  void clear();
  /// The lags with at least kMinimumPairs pairs.
  DisplacementProfile profile() const;

  static constexpr std::size_t kMinimumPairs = 5;
  static constexpr std::array<double, 6> kLags = {0.125, 0.25, 0.5, 1.0, 2.0, 4.0};

 private:
  struct Sample {
    double t;
    Eigen::Vector3d position;
  };
  std::deque<Sample> recent_;  ///< the measurements of the last longest lag (and its tolerance)
  /// Column b: the sums of squared displacements per axis of the pairs at lag b.
  Eigen::Matrix<double, 3, static_cast<int>(kLags.size())> squares_ =
      Eigen::Matrix<double, 3, static_cast<int>(kLags.size())>::Zero();
  std::array<double, kLags.size()> lag_sums_{};
  std::array<std::size_t, kLags.size()> pairs_{};
};

}  // namespace opf
