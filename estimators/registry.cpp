#include "opf/estimators/registry.h"

#include "opf/estimators/cv_kalman.h"
#include "opf/estimators/imm_kalman.h"
#include "opf/estimators/object_permanence_filter.h"
#include "opf/estimators/random_walk_oapf.h"
#include "opf/estimators/standard_pf.h"

#include <stdexcept>

namespace opf {

EstimatorFactory make_estimator_factory(const std::string& name,
                                        const EstimatorSettings& settings) {
  // Options are validated here, when the factory is made, so a bad config fails at start-up and
  // not at the first detection.
  if (name == "opf") {
    OpfOptions options = settings.opf;
    options.particles = settings.pf;
    validate(options);
    return [options](const std::string& object, std::uint64_t seed) {
      return std::make_unique<ObjectPermanenceFilter>(options, object, seed);
    };
  }
  if (name == "pf") {
    validate(settings.pf);
    return [options = settings.pf](const std::string&, std::uint64_t seed) {
      return std::make_unique<StandardParticleFilter>(options, seed);
    };
  }
  if (name == "cvkf") {
    const ConstantVelocityKalman probe(settings.cvkf);  // its constructor validates
    return [options = settings.cvkf](const std::string&, std::uint64_t) {
      return std::make_unique<ConstantVelocityKalman>(options);
    };
  }
  if (name == "imm") {
    const ImmKalman probe(settings.imm);  // its constructor validates
    return [options = settings.imm](const std::string&, std::uint64_t) {
      return std::make_unique<ImmKalman>(options);
    };
  }
  if (name == "oapf") {
    OcclusionAwarePfOptions options = settings.oapf;
    options.particles = settings.pf;
    validate(options);
    return [options](const std::string&, std::uint64_t seed) {
      return std::make_unique<OcclusionAwareParticleFilter>(options, seed);
    };
  }
  throw std::invalid_argument(unknown_estimator_message(name));
}

}  // namespace opf
