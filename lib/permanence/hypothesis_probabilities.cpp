#include "opf/permanence/hypothesis_probabilities.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace opf {

double no_detection_likelihood(double seen) {
  return 1.0 - seen * (1.0 - kDetectorMissProbability);
}

std::vector<std::size_t> hypothesis_order(std::span<const double> probabilities) {
  std::vector<std::size_t> order(probabilities.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (order.size() < 2) return order;
  const auto more_probable = [&](std::size_t a, std::size_t b) {
    return probabilities[a] > probabilities[b];
  };
  // A near tie must not make the main estimate jump between places (a carrier's partial view, the
  // edge of an approaching hand): it changes hands on substantial evidence only.
  const double best_other = *std::max_element(probabilities.begin() + 1, probabilities.end());
  const bool keep_main = best_other < kSubstantialBayesFactor * probabilities[0];
  std::stable_sort(order.begin() + (keep_main ? 1 : 0), order.end(), more_probable);
  std::size_t kept = 1;
  while (kept < order.size() && probabilities[order[kept]] >= kNegligibleProbability) ++kept;
  order.resize(kept);
  return order;
}

std::size_t most_probable_given(std::span<const double> probabilities,
                                std::span<const double> log_evidence) {
  if (probabilities.empty() || probabilities.size() != log_evidence.size())
    throw std::invalid_argument(
        "most_probable_given: needs one evidence per hypothesis, and a hypothesis");
  std::size_t best = 0;
  double best_posterior = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < probabilities.size(); ++i) {
    const double posterior = std::log(probabilities[i]) + log_evidence[i];
    if (posterior > best_posterior) {
      best = i;
      best_posterior = posterior;
    }
  }
  return best;
}

}  // namespace opf
