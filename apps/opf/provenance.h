#pragma once
// The record a result file carries of how it was made: the toolkit's version and commit, the
// command line, and the full effective estimator settings (every option, not only those changed),
// so that a number in a table can be traced to, and rerun from, exactly what produced it.

#include "opf/estimators/estimator_settings.h"

#include <string>
#include <utility>
#include <vector>

namespace opf::cli {

/// "opf <subcommand> <args...>", each argument quoted for a POSIX shell when it needs it.
std::string command_line(const std::string& subcommand, const std::vector<std::string>& args);

/// The JSON object {"version", "commit", "command", "settings"}, its lines indented by `indent`
/// spaces after the first. With one entry named "" the settings are that entry's; with several
/// (one per experiment) they are an object keyed by the names.
std::string provenance_json(const std::string& command,
                            const std::vector<std::pair<std::string, EstimatorSettings>>& settings,
                            std::size_t indent = 0);

}  // namespace opf::cli
