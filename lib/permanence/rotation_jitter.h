#pragma once
// The detector's own rotation noise, read from its detections. The configured observation noise
// is a guess made before the data (0.05 rad by default); real detectors are often far better (the
// in-plane angle of a box from image moments jitters by 2.5 mrad) or worse, and a particle filter
// whose likelihood is wider than the detector's noise trails every turn by a share of it.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <deque>
#include <optional>
#include <vector>

namespace opf {

/// The second differences of consecutive orientations at equal intervals (their two tangent
/// increments subtracted), per body axis, read as noise (second_difference_noise.h). Kept over
/// the last `window` seconds; a gap (an interval unlike the one before) starts them afresh.
class RotationJitter {
 public:
  explicit RotationJitter(double window) : window_(window) {}

  /// A measured orientation at time t (after the previous one).
  void add(double t, const Eigen::Quaterniond& measured);
  void clear();
  /// The noise's standard deviation (rad), of the noisiest body axis (one spread serves all three
  /// in the filter's likelihood, and must not over-trust any); nothing before kMinimumDifferences
  /// differences are in.
  std::optional<double> sigma();

  static constexpr std::size_t kMinimumDifferences = 8;

 private:
  struct Difference {
    double t;
    Eigen::Vector3d squares;  ///< per body axis
  };
  double window_;
  std::deque<Difference> differences_;
  std::optional<double> last_t_;
  Eigen::Quaterniond last_orientation_ = Eigen::Quaterniond::Identity();
  std::optional<Eigen::Vector3d> last_increment_;
  double last_interval_ = 0.0;
  std::vector<double> scratch_;  ///< reused by sigma(): no allocation per frame
};

}  // namespace opf
