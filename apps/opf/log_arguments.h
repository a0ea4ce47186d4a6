#pragma once
// The options of the subcommands that read a user's measurement log (track, evaluate): units,
// column names, frame tolerance and gap filling, mapped onto LogReadOptions.

#include "arguments.h"
#include "opf/io/log_read_options.h"
#include "opf/io/measurement_log.h"

#include <string>
#include <vector>

namespace opf::cli {

std::vector<OptionSpec> log_option_specs();

/// The LogReadOptions the options of log_option_specs() give for the log at `path` ("-": standard
/// input), its format detected unless --format names it; throws UsageError naming the option
/// for a bad value.
LogReadOptions log_options_from(const Arguments& args, const std::string& path);

/// The log at `path` read whole, with a warning on standard error ("opf COMMAND: warning: ...")
/// for each object whose quaternions look written w first (io/quaternion_order_check.h), and
/// note_positions_only's note for a log of positions alone, unless `quiet`.
MeasurementLog read_whole_log(const std::string& path, const LogReadOptions& options,
                              const std::string& command, bool quiet);

/// "opf COMMAND: note: PATH: " and positions_only_note() on standard error.
void note_positions_only(const std::string& command, const std::string& path);

}  // namespace opf::cli
