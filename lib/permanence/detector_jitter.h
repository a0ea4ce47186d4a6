#pragma once
// The detector's own noise, read from its detections: its rotation noise, and its position noise.
// The configured observation noise is a guess made before the data (0.05 rad by default); real
// detectors are often far better (the in-plane angle of a box from image moments jitters by 2.5
// mrad) or worse. A particle filter whose likelihood is wider than the detector's noise trails
// every turn by a share of it.
//
// The reading: the second difference of three orientations at equal intervals (two tangent
// increments subtracted) is mostly noise, N(0, 6 sigma^2) per body axis, for a turn that is
// smooth over two frames; the median of its squares is 6 sigma^2 times 0.4549 (the median of
// chi-square with one degree of freedom), which ignores the few differences a sudden turn or an
// outlier inflates. The same reading of the positions' second differences per world axis gives
// the position noise.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <deque>
#include <optional>
#include <vector>

namespace opf {

/// The second differences of consecutive orientations (tangent increments per body axis) and
/// positions (per world axis), kept over the last `window` seconds; a gap (an interval unlike the
/// one before) starts them afresh. Each axis's squares are also kept sorted, so the median read
/// every frame costs a binary search and a short move per frame, not a selection over the window
/// (same values: the median is the same element).
class DetectorJitter {
 public:
  explicit DetectorJitter(double window) : window_(window) {}

  /// A measured pose at time t (after the previous one).
  void add(double t, const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation);
  void clear();
  /// The rotation noise's standard deviation (rad), of the noisiest body axis (one spread serves
  /// all three in the filter's likelihood, and must not over-trust any); nothing before
  /// kMinimumDifferences differences are in.
  std::optional<double> rotation_sigma() const;
  /// The position noise's standard deviation (m), of the noisiest world axis; nothing before
  /// kMinimumDifferences differences are in.
  std::optional<double> translation_sigma() const;

  static constexpr std::size_t kMinimumDifferences = 8;

 private:
  static constexpr std::size_t kAxes = 6;  ///< the body's rotation axes, then the world's
  struct Difference {
    double t;
    Eigen::Matrix<double, kAxes, 1> squares;
  };
  std::optional<double> sigma(std::size_t first_axis) const;
  void insert(const Difference& d);
  void erase(const Difference& d);

  double window_;
  std::deque<Difference> differences_;
  std::optional<double> last_t_;
  Eigen::Quaterniond last_orientation_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d last_position_ = Eigen::Vector3d::Zero();
  std::optional<Eigen::Matrix<double, kAxes, 1>> last_increment_;  ///< tangent, then position
  double last_interval_ = 0.0;
  std::array<std::vector<double>, kAxes> sorted_;  ///< each axis's squares, ascending
};

}  // namespace opf
