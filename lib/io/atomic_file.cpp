#include "opf/io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace opf {

namespace {

// The temporaries being written, where a signal handler can reach them: static storage is all it
// may touch. A slot is claimed (0 -> 1) by the writer, filled, published (-> 2), and freed (-> 0)
// once its file is renamed into place, or before it is removed; the handler unlinks the published
// ones (one renamed a moment before is gone already: the unlink fails harmlessly).
struct PendingTemporary {
  std::atomic<int> state{0};
  char path[4096] = {};
};
constexpr std::size_t kPendingSlots = 32;
PendingTemporary g_pending[kPendingSlots];  // NOLINT: reached from signal handlers

/// Removes the temporary unless released, whichever way the scope is left; while it exists, a
/// signal handler calling remove_open_temporary_files() removes it too.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::filesystem::path path) : path_(std::move(path)) {
    const std::string text = path_.string();
    for (PendingTemporary& slot : g_pending) {
      int free = 0;
      if (text.size() >= sizeof slot.path || !slot.state.compare_exchange_strong(free, 1)) continue;
      text.copy(slot.path, text.size());
      slot.path[text.size()] = '\0';
      slot.state.store(2);
      slot_ = &slot;
      break;
    }
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    unpublish();
    std::error_code ignored;
    if (!released_) std::filesystem::remove(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  /// After the rename: the file is the result now, not a temporary.
  void release() {
    unpublish();
    released_ = true;
  }

 private:
  void unpublish() {
    if (slot_) slot_->state.store(0);
    slot_ = nullptr;
  }

  std::filesystem::path path_;
  PendingTemporary* slot_ = nullptr;  ///< none when every slot is taken: not reachable then
  bool released_ = false;
};

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error("cannot write '" + path.string() + "': " + what);
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  // Through a symbolic link the file it names is replaced, not the link (as an editor saves).
  std::error_code no_such_file;  // a path that does not exist yet is no link
  std::filesystem::path target = path;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(path, no_such_file))) {
    std::error_code ec;
    target = std::filesystem::weakly_canonical(path, ec);
    if (ec) fail(path, "cannot follow the link: " + ec.message());
  }
  // A sibling, so the rename stays within one file system; the pid keeps concurrent runs apart.
  std::filesystem::path temporary_path = target;
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
  std::filesystem::rename(temporary.path(), target, ec);
  if (ec) fail(path, "cannot rename the temporary file into place: " + ec.message());
  temporary.release();
}

void remove_open_temporary_files() noexcept {
  for (PendingTemporary& slot : g_pending)
    if (slot.state.load() == 2) ::unlink(slot.path);
}

}  // namespace opf
