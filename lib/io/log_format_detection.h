#pragma once
// Which format a log file is in, from its name and first line, so that a TUM trajectory tracks
// without an option.

#include "opf/io/log_read_options.h"

#include <filesystem>
#include <string_view>

namespace opf {

/// When `first_line` (the file's first non-blank line) starts with '#': kEuroc if
/// `first_data_line` (the first non-blank line not starting with '#') is eight or more numbers
/// separated by commas, else kTum. Otherwise kTum when the file name ends in .tum, or in .txt with
/// a first line of eight numbers separated by spaces or tabs; kMot for a .txt whose first line is
/// seven or more numbers separated by commas (gt.txt, det.txt); kKitti for a .txt whose first line
/// is a KITTI tracking label (a frame, a track id, a type word and 14 or 15 numbers separated by
/// spaces); kCsv otherwise.
LogFormat detect_log_format(const std::filesystem::path& name, std::string_view first_line,
                            std::string_view first_data_line = {});

/// The same for the file at `path`, its first line read; kCsv for what is not a regular file (a
/// pipe is read once, so its first line cannot be looked at first).
LogFormat detect_log_format(const std::filesystem::path& path);

}  // namespace opf
