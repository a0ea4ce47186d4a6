#pragma once
// The options every estimator-running subcommand shares: --config, --particles, --seed,
// --threads.

#include "arguments.h"
#include "estimators/estimator_settings.h"

#include <cstdint>
#include <vector>

namespace opf::cli {

std::vector<OptionSpec> estimator_option_specs();

/// `base` (the defaults unless given), then the YAML file of --config, then --particles (both
/// portions).
EstimatorSettings settings_from(const Arguments& args, const EstimatorSettings& base = {});

/// --threads, or the machine's hardware threads.
std::size_t threads_from(const Arguments& args);

/// --seed, or the toolkit's default seed.
std::uint64_t seed_from(const Arguments& args);

constexpr std::uint64_t kDefaultSeed = 1;

}  // namespace opf::cli
