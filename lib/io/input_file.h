#pragma once
// Opens an input file for reading with the errors every reader wants: missing file, a directory
// (which std::ifstream "opens" and reads as empty, i.e. silently as no data), or no permission,
// each an InputError naming the path and what kind of file was expected.

#include <filesystem>
#include <fstream>
#include <string_view>

namespace opf {

/// `what` names the file's role in messages, e.g. "measurement log".
std::ifstream open_input_file(const std::filesystem::path& path, std::string_view what);

/// Whether `path` names a regular file. A path the system cannot look up (too long for a file
/// name, say) names none, rather than throwing std::filesystem::filesystem_error: readers that
/// resolve a path from a file's text report it as missing, at the key that names it.
bool names_regular_file(const std::filesystem::path& path);

}  // namespace opf
