#pragma once
// The weights of a bank of models under Bayesian model averaging with forgetting in continuous
// time (motion_model_bank.h, rotation_model_bank.h): after a step dt, with member j's one-step
// predictive log-likelihood l_j and prior pi_j,
//
//   log w_j <- lambda log w_j + (1 - lambda) log pi_j + l_j,   lambda = exp(-dt / T_memory),
//
// normalised and floored (renormalised), so that no member dies for good.

#include "opf/particles/log_weights.h"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace opf {

/// The floor of a member's probability.
inline constexpr double kModelWeightFloor = 1e-12;

/// The banks' priors: each model 1 / (number of models), shared equally by its members;
/// `model_of_member` names each member's model by any integer.
std::vector<double> equal_model_priors(std::span<const int> model_of_member);

class ModelWeights {
 public:
  /// Starts at the priors (positive, normalised here).
  explicit ModelWeights(std::vector<double> priors);

  /// Back to the priors.
  void reset();
  /// One step of dt (s) with the members' log-likelihoods, memory T_memory (s).
  void update(double dt, double memory, std::span<const double> log_likelihoods);

  std::span<const double> weights() const {
    return {weights_.data(), static_cast<std::size_t>(weights_.size())};
  }
  std::size_t size() const { return static_cast<std::size_t>(weights_.size()); }

 private:
  void normalise();

  Eigen::VectorXd log_priors_;
  LogWeights log_weights_;  ///< normalised in one vectorised pass, as the particles' weights
  Eigen::VectorXd weights_;
};

}  // namespace opf
