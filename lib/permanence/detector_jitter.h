#pragma once
// The detector's own noise, read from its detections. The configured observation noise is a
// guess made before the data (0.01 m and 0.05 rad by default); real detectors are often far
// better (the in-plane angle of a box from image moments jitters by 2.5 mrad, its centroid by a
// third of a millimetre) or worse, and often unevenly (a depth read from an object's apparent
// size jitters ten times more than its image-plane position). A particle filter whose likelihood
// is wider than the detector's noise trails every turn by a share of it.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <deque>
#include <optional>
#include <vector>

namespace opf {

/// The second differences of consecutive measurements at equal intervals (their two increments
/// subtracted: positions per world axis, orientations as tangent increments per body axis), read
/// as noise (second_difference_noise.h). Kept over the last `window` seconds; a gap (an interval
/// unlike the one before) starts them afresh. Each coordinate's squares are also kept sorted, so
/// the median read every frame costs a binary search and a short move per frame, not a selection
/// over the window (same values: the median is the same element).
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
  /// The position noise's standard deviation (m) per world axis; nothing before
  /// kMinimumDifferences differences are in.
  std::optional<Eigen::Vector3d> translation_sigmas() const;

  static constexpr std::size_t kMinimumDifferences = 8;

 private:
  struct Difference {
    double t;
    Eigen::Vector3d translation_squares;  ///< per world axis
    Eigen::Vector3d rotation_squares;     ///< per body axis
    double square(int channel) const;
  };
  /// The six coordinates' squares: translation per world axis, then rotation per body axis.
  static constexpr int kChannels = 6;
  Eigen::Vector3d sigmas(int first_channel) const;
  void insert(const Difference& d);
  void erase(const Difference& d);

  double window_;
  std::deque<Difference> differences_;
  std::optional<double> last_t_;
  Eigen::Vector3d last_position_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond last_orientation_ = Eigen::Quaterniond::Identity();
  std::optional<Eigen::Vector3d> last_step_;  ///< position increment
  std::optional<Eigen::Vector3d> last_turn_;  ///< tangent increment
  double last_interval_ = 0.0;
  std::array<std::vector<double>, kChannels> sorted_;  ///< each channel's squares, ascending
};

}  // namespace opf
