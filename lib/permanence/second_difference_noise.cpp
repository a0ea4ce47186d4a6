#include "opf/permanence/second_difference_noise.h"

#include <algorithm>
#include <cstddef>

namespace opf {

double noise_variance_from_second_differences(std::vector<double>& squares) {
  if (squares.empty()) return 0.0;
  constexpr double kChiSquareOneMedian = 0.4549;
  const auto middle = squares.begin() + static_cast<std::ptrdiff_t>(squares.size() / 2);
  std::nth_element(squares.begin(), middle, squares.end());
  return *middle / (6.0 * kChiSquareOneMedian);
}

}  // namespace opf
