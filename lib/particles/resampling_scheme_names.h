#pragma once
// The names of the resampling schemes as config files and the command line spell them.

#include "opf/particles/particle_filter_options.h"

#include <string_view>

namespace opf {

/// "multinomial", "residual", "stratified" or "systematic". Throws std::invalid_argument listing
/// the four for any other name.
ResamplingScheme parse_resampling_scheme(std::string_view name);

/// The name parse_resampling_scheme reads back.
std::string_view to_string(ResamplingScheme scheme);

}  // namespace opf
