#include "opf/permanence/weighted_choice.h"

#include <algorithm>
#include <stdexcept>

namespace opf {

std::size_t weighted_choice(std::span<const double> weights, double uniform01) {
  double total = 0.0;
  for (const double w : weights) total += w;
  if (weights.empty() || !(total > 0.0))
    throw std::invalid_argument("weighted_choice: the weights must have a positive sum");
  const double target = std::clamp(uniform01, 0.0, 1.0) * total;
  double cumulative = 0.0;
  std::size_t last_positive = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (weights[i] <= 0.0) continue;
    cumulative += weights[i];
    last_positive = i;
    if (target < cumulative) return i;
  }
  return last_positive;  // u = 1, or rounding in the sum
}

}  // namespace opf
