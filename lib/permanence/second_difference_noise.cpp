#include "opf/permanence/second_difference_noise.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace opf {

namespace {

double noise_variance_from_median(double median) {
  constexpr double kChiSquareOneMedian = 0.4549;
  return median / (6.0 * kChiSquareOneMedian);
}

}  // namespace

double noise_variance_from_second_differences(std::vector<double>& squares) {
  if (squares.empty()) return 0.0;
  const auto middle = squares.begin() + static_cast<std::ptrdiff_t>(squares.size() / 2);
  std::nth_element(squares.begin(), middle, squares.end());
  return noise_variance_from_median(*middle);
}

double noise_variance_from_sorted_squares(const std::vector<double>& sorted) {
  if (sorted.empty()) return 0.0;
  return noise_variance_from_median(sorted[sorted.size() / 2]);
}

Eigen::Vector3d noise_variance_per_axis(const Eigen::Matrix3Xd& values) {
  const Eigen::Index n = values.cols();
  if (n < 3) return Eigen::Vector3d::Zero();
  Eigen::Vector3d variance;
  std::vector<double> squares(static_cast<std::size_t>(n - 2));
  for (int axis = 0; axis < 3; ++axis) {
    for (Eigen::Index k = 1; k + 1 < n; ++k) {
      const double d = values(axis, k + 1) - 2.0 * values(axis, k) + values(axis, k - 1);
      squares[static_cast<std::size_t>(k - 1)] = d * d;
    }
    variance(axis) = noise_variance_from_second_differences(squares);
  }
  return variance;
}

}  // namespace opf
