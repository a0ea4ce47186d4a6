#pragma once
// A sweep's runs as JSON, for workflow engines (workflow/Snakefile): what each run writes, its
// settings and the `opf` arguments that run it, so the expansion lives in one place.

#include "drivers/sweep_runs.h"

#include <filesystem>
#include <ostream>
#include <vector>

namespace opf::experiments {

/// {"name": ..., "sweep": <file>, "out": <out>, "table": <out>/<name>.csv, "runs": [{"directory",
/// "result" (both relative to out), "settings_yaml", "arguments" (after `opf`)}, ...]}, with
/// `out` made absolute.
void write_sweep_plan(std::ostream& json, const SweepSpec& spec, const std::vector<SweepRun>& runs,
                      const std::filesystem::path& out);

}  // namespace opf::experiments
