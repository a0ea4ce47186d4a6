#include "output_paths.h"

#include "arguments.h"

#include <filesystem>
#include <system_error>

namespace opf::cli {
namespace {

namespace fs = std::filesystem;

// One file: the same existing file (also through a link), or the same path once the links of
// its existing part are resolved (two outputs that do not exist yet).
bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec)) return true;
  const auto canonical = [&ec](const std::string& path) {
    const fs::path absolute = fs::absolute(path, ec);
    return ec ? fs::path() : fs::weakly_canonical(absolute, ec);
  };
  const fs::path canonical_a = canonical(a);
  if (ec) return false;
  const fs::path canonical_b = canonical(b);
  return !ec && canonical_a == canonical_b;
}

}  // namespace

void refuse_output_over_input(const NamedPath& output, std::initializer_list<NamedPath> inputs) {
  if (output.path.empty() || output.path == "-") return;
  for (const NamedPath& input : inputs) {
    if (input.path.empty() || input.path == "-" || !same_file(output.path, input.path)) continue;
    throw UsageError{output.argument + " '" + output.path + "' is the same file as " +
                     input.argument + " '" + input.path +
                     "': one would overwrite the other; write to another file"};
  }
}

void require_folder(const NamedPath& folder) {
  std::error_code ec;
  const fs::file_status status = fs::status(folder.path, ec);
  if (ec || !fs::exists(status) || fs::is_directory(status)) return;
  throw UsageError{folder.argument + " '" + folder.path +
                   "' is a file: it names the folder the results go to"};
}

}  // namespace opf::cli
