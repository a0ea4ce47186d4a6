#pragma once
// Writes a file all-or-nothing, so an interrupted or failed run never leaves a partial result file
// that looks complete.

#include <filesystem>
#include <functional>
#include <ostream>

namespace opf {

/// Calls `write` on a stream to a temporary file next to `path`, checks the stream, then renames
/// the temporary over `path` (atomic on POSIX within one file system); a symbolic link `path` is
/// followed, and the file it names replaced. If `write` throws or the
/// file cannot be written, the temporary is removed, `path` is left untouched and the exception
/// propagates; I/O failures throw std::runtime_error naming the path.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

/// Removes every temporary file write_file_atomically has open in this process. Async-signal-safe
/// (unlink(2) only): a program's SIGINT / SIGTERM handler calls it so that an interrupted run
/// leaves no temporary behind (`opf` does; a library user decides for their own handlers).
void remove_open_temporary_files() noexcept;

}  // namespace opf
