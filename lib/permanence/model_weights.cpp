#include "opf/permanence/model_weights.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace opf {

std::vector<double> equal_model_priors(std::span<const int> model_of_member) {
  std::vector<int> models(model_of_member.begin(), model_of_member.end());
  std::sort(models.begin(), models.end());
  const auto model_count =
      static_cast<double>(std::unique(models.begin(), models.end()) - models.begin());
  std::vector<double> priors;
  for (const int m : model_of_member) {
    const auto members = std::count(model_of_member.begin(), model_of_member.end(), m);
    priors.push_back(1.0 / (model_count * static_cast<double>(members)));
  }
  return priors;
}

ModelWeights::ModelWeights(std::vector<double> priors)
    : log_priors_(static_cast<Eigen::Index>(priors.size())), log_weights_(priors.size()) {
  double sum = 0.0;
  for (const double p : priors) {
    if (!(p > 0.0) || !std::isfinite(p))
      throw std::invalid_argument("ModelWeights: every prior must be a positive number");
    sum += p;
  }
  if (priors.empty()) throw std::invalid_argument("ModelWeights: no members");
  for (std::size_t j = 0; j < priors.size(); ++j)
    log_priors_[static_cast<Eigen::Index>(j)] = std::log(priors[j] / sum);
  reset();
}

void ModelWeights::reset() {
  log_weights_.log() = log_priors_;
  normalise();
}

void ModelWeights::update(double dt, double memory, std::span<const double> log_likelihoods) {
  if (log_likelihoods.size() != size())
    throw std::invalid_argument("ModelWeights: one log-likelihood per member");
  const double lambda = std::exp(-dt / memory);
  Eigen::VectorXd& log_w = log_weights_.log();
  const Eigen::Map<const Eigen::VectorXd> likelihoods(log_likelihoods.data(), log_w.size());
  log_w = lambda * log_w + (1.0 - lambda) * log_priors_ + likelihoods;
  normalise();
}

void ModelWeights::normalise() {
  // Shifted by the largest before the exponentials, so a very negative log-likelihood (an
  // outlier) cannot underflow every member at once; with none usable (NaN), back to uniform.
  log_weights_.normalise(weights_);
  Eigen::VectorXd& log_w = log_weights_.log();
  const double log_floor = std::log(kModelWeightFloor);
  double floored = 0.0;
  for (Eigen::Index j = 0; j < weights_.size(); ++j) {
    if (weights_[j] < kModelWeightFloor) {
      weights_[j] = kModelWeightFloor;
      log_w[j] = log_floor;
    }
    floored += weights_[j];
  }
  weights_ /= floored;
  log_w.array() -= std::log(floored);
}

}  // namespace opf
