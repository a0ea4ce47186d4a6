#pragma once
// A sweep's results as one tidy table: a row per run with its parameters, read from the runs'
// result files, and a summary over seeds for the terminal.

#include "drivers/sweep_runs.h"

#include <cstddef>
#include <filesystem>
#include <ostream>
#include <vector>

namespace opf::experiments {

/// Writes `csv`: experiment,estimator,variant,<one column per parameter key>,seed, then the
/// metric columns of the runs CSV (translation_error ... miss_distance), then status: "ok", or
/// "missing" (no result file: the run failed or has not run; its metrics are empty). Every run of
/// `runs` has its row, in their order. Returns the number of rows with status ok. Throws
/// InputError when a result file is malformed.
std::size_t write_sweep_table(const SweepSpec& spec, const std::vector<SweepRun>& runs,
                              const std::filesystem::path& out, const std::filesystem::path& csv);

/// Per experiment, estimator, variant and grid point: the translation and geodesic rotation
/// errors as mean +- std over the seeds whose runs are done, from the table `csv`.
void print_sweep_summary(std::ostream& out, const std::filesystem::path& csv);

}  // namespace opf::experiments
