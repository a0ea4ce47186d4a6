#include "opf/io/input_file.h"

#include "opf/io/input_error.h"

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

namespace opf {

std::ifstream open_input_file(const std::filesystem::path& path, std::string_view what) {
  const std::string name(what);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec) && !ec)
    throw InputError(path.string(), 0, "", std::string(name).append(" not found"));
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path.string(), 0, "",
                     std::string("expected a ").append(name).append(" file, got a directory"));
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(
        path.string(), 0, "",
        std::string("cannot open the ").append(name).append(": ").append(std::strerror(errno)));
  return in;
}

bool names_regular_file(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

}  // namespace opf
