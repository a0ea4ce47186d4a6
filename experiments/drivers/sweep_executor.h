#pragma once
// Runs a sweep's runs as `opf run` processes, several at once, skipping those already done.

#include "drivers/sweep_runs.h"

#include <cstddef>
#include <filesystem>
#include <ostream>
#include <vector>

namespace opf::experiments {

struct SweepExecution {
  std::size_t skipped = 0;    ///< done before this call (their result files existed)
  std::size_t completed = 0;  ///< run now, successfully
  /// Runs whose process failed or wrote no result file, by directory; each keeps its log.txt.
  std::vector<std::filesystem::path> failed;
};

/// Runs every run whose result file is missing as `program run ...` (SweepRun::arguments), at
/// most `jobs` at a time, each with its settings.yaml written first and its output in
/// <dir>/log.txt. Reports progress on `progress`: a bar redrawn in place when `interactive`,
/// else a line per finished run.
SweepExecution execute_sweep(const std::vector<SweepRun>& runs, const std::filesystem::path& out,
                             const std::filesystem::path& program, std::size_t jobs,
                             std::ostream& progress, bool interactive);

}  // namespace opf::experiments
