#pragma once
// A measurement's noise read from the measurements themselves: the second difference of three
// samples of a smooth motion at equal intervals is mostly noise, N(0, 6 sigma^2); the median of
// its squares is 6 sigma^2 times 0.4549 (the median of chi-square with one degree of freedom),
// which ignores the few differences a turn or an outlier inflates. The dynamics module reads the
// positions' and rotations' noise this way, the OPF its detector's rotation jitter
// and its positions' noise (the spread at the onset of a gap).

#include <Eigen/Core>

#include <vector>

namespace opf {

/// sigma^2 from the squared second differences of one coordinate (reorders them); 0 for none.
double noise_variance_from_second_differences(std::vector<double>& squares);

/// The same from squares already sorted ascending (their middle element is the median taken
/// above); 0 for none.
double noise_variance_from_sorted_squares(const std::vector<double>& sorted);

/// sigma^2 per row of a series of samples at (nearly) equal intervals, one column a sample: three
/// rows of positions or rotation vectors; zeros under three samples.
Eigen::Vector3d noise_variance_per_axis(const Eigen::Matrix3Xd& values);

}  // namespace opf
