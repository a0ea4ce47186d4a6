#include "opf/core/homogeneous_point.h"

namespace opf {

std::optional<Eigen::Vector4d> homogeneous_point(std::span<const double> numbers) {
  if (numbers.size() != 3 && numbers.size() != 4) return std::nullopt;
  Eigen::Vector4d point(numbers[0], numbers[1], numbers[2], numbers.size() == 4 ? numbers[3] : 1);
  if (!point.allFinite() || (point.w() != 0.0 && point.w() != 1.0) ||
      (point.w() == 0.0 && !(point.head<3>().norm() > 0.0)))
    return std::nullopt;
  return point;
}

}  // namespace opf
