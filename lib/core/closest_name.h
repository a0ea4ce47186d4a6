#pragma once
// The near miss of a mistyped name among the names understood (commands, options, settings keys,
// estimators): what "did you mean ...?" suggests.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace opf {

/// Optimal-string-alignment distance: insertions, deletions, substitutions and swaps of two
/// neighbours, the usual typos, each cost 1.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The known name nearest to `given` by edit_distance when it is a near miss: at most
/// max(2, its length / 3) edits away and fewer than half its length (so "ekf" is not taken for
/// "opf"), or `given` a prefix of it. The first of equally near names; nullopt when none is near.
std::optional<std::string> closest_name(std::string_view given,
                                        const std::vector<std::string>& known);

}  // namespace opf
