#pragma once
// Tracking-error metrics: the paper's (Sec. IV-A) and a geodesic rotation error, plus mean and
// standard deviation over frames and seeds.

#include <mrpt/poses/CPose3D.h>

#include <cstddef>
#include <span>

namespace opf {

/// ||p_est - p_true||_2 of the translations, in metres.
double translation_error(const mrpt::poses::CPose3D& estimate, const mrpt::poses::CPose3D& truth);

/// The paper's rotation error: ||(yaw, pitch, roll)_est - (yaw, pitch, roll)_true||_2 in radians,
/// each angle difference wrapped to [-pi, pi]. It is not a distance on SO(3) (it depends on the
/// parametrisation and misbehaves near pitch = +-pi/2); reported for comparability with Table I.
double rotation_error_paper(const mrpt::poses::CPose3D& estimate,
                            const mrpt::poses::CPose3D& truth);

/// The geodesic rotation error: the angle of R_est^T R_true, in [0, pi] radians.
double rotation_error_geodesic(const mrpt::poses::CPose3D& estimate,
                               const mrpt::poses::CPose3D& truth);

struct MeanStd {
  double mean = 0.0;
  double std = 0.0;       ///< sample standard deviation (n - 1); 0 for fewer than two values
  std::size_t count = 0;  ///< the values it is over (0: not recorded)

  /// Whether `std` describes a spread: over two values or more, or given without a count.
  bool has_spread() const { return count != 1; }
};

/// Mean and sample standard deviation; throws std::invalid_argument on an empty input.
MeanStd mean_std(std::span<const double> values);

}  // namespace opf
