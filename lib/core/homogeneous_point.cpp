#include "opf/core/homogeneous_point.h"

#include <cstdlib>
#include <sstream>
#include <vector>

namespace opf {

std::optional<Eigen::Vector4d> homogeneous_point(std::span<const double> numbers) {
  if (numbers.size() != 3 && numbers.size() != 4) return std::nullopt;
  Eigen::Vector4d point(numbers[0], numbers[1], numbers[2], numbers.size() == 4 ? numbers[3] : 1);
  if (!point.allFinite() || (point.w() != 0.0 && point.w() != 1.0) ||
      (point.w() == 0.0 && !(point.head<3>().norm() > 0.0)))
    return std::nullopt;
  return point;
}

std::optional<Eigen::Vector4d> homogeneous_point_from_text(const std::string& text) {
  std::vector<double> numbers;
  std::stringstream parts(text);
  for (std::string part; std::getline(parts, part, ',');) {
    if (part.empty()) continue;
    char* end = nullptr;
    numbers.push_back(std::strtod(part.c_str(), &end));
    if (end == part.c_str() || *end != '\0') return std::nullopt;
  }
  return homogeneous_point(numbers);
}

}  // namespace opf
