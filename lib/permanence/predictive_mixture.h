#pragma once
// A Gaussian mixture's summary on one axis: what a motion-model bank (motion_model_bank.h)
// predicts for a horizon, one component per member with its weight, and the mixture's mean and
// variance (its first two moments, the law of total variance).

#include <string_view>
#include <vector>

namespace opf {

/// One member's prediction of the position on one axis (m, m^2), with its weight.
struct MemberPrediction {
  std::string_view model;  ///< model_name() of the member's model
  double weight = 0.0;
  double mean = 0.0;
  double variance = 0.0;
};

/// The mixture sum_j w_j N(mean_j, variance_j) on one axis (weights summing to 1).
struct AxisMixture {
  std::vector<MemberPrediction> members;

  /// sum_j w_j mean_j.
  double mean() const;
  /// sum_j w_j (variance_j + (mean_j - mean)^2).
  double variance() const;
};

}  // namespace opf
