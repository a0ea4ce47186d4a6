#include "opf/particles/resampling_scheme_names.h"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace opf {

namespace {

using PF = mrpt::bayes::CParticleFilter;

constexpr std::array<std::pair<std::string_view, ResamplingScheme>, 4> kSchemes = {{
    {"multinomial", PF::prMultinomial},
    {"residual", PF::prResidual},
    {"stratified", PF::prStratified},
    {"systematic", PF::prSystematic},
}};

}  // namespace

ResamplingScheme parse_resampling_scheme(std::string_view name) {
  for (const auto& [known, scheme] : kSchemes)
    if (known == name) return scheme;
  throw std::invalid_argument("unknown resampling scheme '" + std::string(name) +
                              "': expected multinomial, residual, stratified or systematic");
}

std::string_view to_string(ResamplingScheme scheme) {
  for (const auto& [name, known] : kSchemes)
    if (known == scheme) return name;
  throw std::invalid_argument("unknown resampling scheme value " +
                              std::to_string(static_cast<int>(scheme)));
}

}  // namespace opf
