#include "opf/io/atomic_file.h"

#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace opf {

namespace {

/// Removes the temporary unless released, whichever way the scope is left.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::filesystem::path path) : path_(std::move(path)) {}
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    std::error_code ignored;
    if (!released_) std::filesystem::remove(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  void release() { released_ = true; }

 private:
  std::filesystem::path path_;
  bool released_ = false;
};

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error("cannot write '" + path.string() + "': " + what);
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  // A sibling, so the rename stays within one file system; the pid keeps concurrent runs apart.
  std::filesystem::path temporary_path = path;
  temporary_path += ".tmp." + std::to_string(::getpid());
  TemporaryFile temporary(temporary_path);

  {
    std::ofstream out(temporary.path(), std::ios::binary | std::ios::trunc);
    if (!out) fail(path, "cannot create the temporary file '" + temporary.path().string() + "'");
    write(out);
    out.flush();
    if (!out) fail(path, "write error");
    out.close();
    if (!out) fail(path, "write error on close");
  }

  std::error_code ec;
  std::filesystem::rename(temporary.path(), path, ec);
  if (ec) fail(path, "cannot rename the temporary file into place: " + ec.message());
  temporary.release();
}

}  // namespace opf
