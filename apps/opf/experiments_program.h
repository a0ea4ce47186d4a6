#pragma once
// `opf-experiments`: the program that runs the commands which render scenes or read video
// (OpenCV, MRPT's OpenGL), installed as <libexecdir>/opf/opf-experiments beside <bindir>/opf,
// as git keeps its subcommand programs. `opf` runs it in its own place for those commands, so
// that the commands which only track never load those libraries.

namespace opf::cli {

/// Replaces this process with the experiments program, given the same arguments. Returns only
/// by throwing std::runtime_error, naming the program and why it could not be run.
[[noreturn]] void run_experiments_program(char** argv);

}  // namespace opf::cli
