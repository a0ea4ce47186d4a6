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

ModelWeights::ModelWeights(std::vector<double> priors) : weights_(priors.size(), 0.0) {
  double sum = 0.0;
  for (const double p : priors) {
    if (!(p > 0.0) || !std::isfinite(p))
      throw std::invalid_argument("ModelWeights: every prior must be a positive number");
    sum += p;
  }
  if (priors.empty()) throw std::invalid_argument("ModelWeights: no members");
  for (const double p : priors) log_priors_.push_back(std::log(p / sum));
  reset();
}

void ModelWeights::reset() {
  log_weights_ = log_priors_;
  normalise();
}

void ModelWeights::update(double dt, double memory, std::span<const double> log_likelihoods) {
  if (log_likelihoods.size() != log_weights_.size())
    throw std::invalid_argument("ModelWeights: one log-likelihood per member");
  const double lambda = std::exp(-dt / memory);
  for (std::size_t j = 0; j < log_weights_.size(); ++j)
    log_weights_[j] =
        lambda * log_weights_[j] + (1.0 - lambda) * log_priors_[j] + log_likelihoods[j];
  normalise();
}

void ModelWeights::normalise() {
  // exp relative to the largest, so a very negative log-likelihood (an outlier) cannot underflow
  // every member at once; the logs are shifted rather than recomputed, except where floored.
  const double top = *std::max_element(log_weights_.begin(), log_weights_.end());
  double sum = 0.0;
  for (std::size_t j = 0; j < weights_.size(); ++j)
    sum += weights_[j] = std::exp(log_weights_[j] - top);
  const double log_sum = top + std::log(sum);
  const double log_floor = std::log(kModelWeightFloor);
  double floored = 0.0;
  for (std::size_t j = 0; j < weights_.size(); ++j) {
    weights_[j] /= sum;
    if (weights_[j] < kModelWeightFloor) {
      weights_[j] = kModelWeightFloor;
      log_weights_[j] = log_floor;
    } else {
      log_weights_[j] -= log_sum;
    }
    floored += weights_[j];
  }
  const double log_floored = std::log(floored);
  for (std::size_t j = 0; j < weights_.size(); ++j) {
    weights_[j] /= floored;
    log_weights_[j] -= log_floored;
  }
}

}  // namespace opf
