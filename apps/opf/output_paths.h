#pragma once
// Outputs must not replace the command's own inputs (`opf dropout --in log.csv --out log.csv`
// would destroy the log its removed frames are scored against), nor each other, and a folder
// for results must not be a file.

#include <initializer_list>
#include <string>

namespace opf::cli {

/// A file a command-line argument names ("-": standard input or output, never a file; empty: not
/// given).
struct NamedPath {
  std::string argument;  ///< as the user knows it: "--in", "the experiment file"
  std::string path;
};

/// Throws UsageError when `output` names the same file as one of `inputs` (also through a link
/// or another spelling of the path): "--out 'X' is the same file as --in 'Y': one would overwrite
/// the other; write to another file". An "input" may be another output of the command that does
/// not exist yet: two outputs of one path would overwrite each other.
void refuse_output_over_input(const NamedPath& output, std::initializer_list<NamedPath> inputs);

/// Throws UsageError when `folder` (an output folder, created where missing) names something that
/// exists and is not a folder: "--out 'X' is a file: it names the folder the results go to".
void require_folder(const NamedPath& folder);

}  // namespace opf::cli
