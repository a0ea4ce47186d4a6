#include "estimators/registry.h"

#include "estimators/cv_kalman.h"
#include "estimators/standard_pf.h"

#include <stdexcept>

namespace opf {

std::vector<std::string> estimator_names() {
  return {"pf", "cvkf"};
}

EstimatorFactory make_estimator_factory(const std::string& name,
                                        const EstimatorSettings& settings) {
  if (name == "pf") {
    validate(settings.pf);  // fail at start-up, not at the first detection
    return [options = settings.pf](const std::string&, std::uint64_t seed) {
      return std::make_unique<StandardParticleFilter>(options, seed);
    };
  }
  if (name == "cvkf") {
    ConstantVelocityKalman probe(settings.cvkf);  // validates the options now
    return [options = settings.cvkf](const std::string&, std::uint64_t) {
      return std::make_unique<ConstantVelocityKalman>(options);
    };
  }
  std::string known;
  for (const auto& n : estimator_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown estimator '" + name + "' (known: " + known + ")");
}

}  // namespace opf
