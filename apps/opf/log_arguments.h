#pragma once
// The options of the subcommands that read a user's measurement log (track, evaluate): units,
// column names, frame tolerance and gap filling, mapped onto LogReadOptions.

#include "arguments.h"
#include "opf/io/log_read_options.h"

#include <vector>

namespace opf::cli {

std::vector<OptionSpec> log_option_specs();

/// The LogReadOptions the options of log_option_specs() give; throws UsageError naming the option
/// for a bad value.
LogReadOptions log_options_from(const Arguments& args);

}  // namespace opf::cli
