#include "sweep_command.h"

#include "arguments.h"
#include "command_help.h"
#include "drivers/experiment_run.h"
#include "drivers/sweep_executor.h"
#include "drivers/sweep_plan.h"
#include "drivers/sweep_table.h"
#include "estimator_arguments.h"
#include "opf/io/atomic_file.h"
#include "opf/io/estimator_settings_yaml.h"
#include "opf/sim/experiment_config.h"
#include "output_paths.h"
#include "provenance.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <thread>

namespace opf::cli {
namespace {

std::vector<OptionSpec> specs() {
  return {
      {"out", "DIR",
       "where the runs and the table go (default: results/sweeps/<sweep name>, or "
       "results/sweeps/<sweep name>-paper with --preset paper)"},
      {"preset", "NAME",
       "default or paper: the settings every run starts from, the sweep's own on top (as "
       "`opf run --preset`)"},
      {"jobs", "N", "runs at once, each on one thread (default: the machine's cores)"},
      {"list", "", "print the runs (and which are done) without running anything"},
      {"plan", "", "print the runs as JSON (for workflow/Snakefile) without running anything"},
      {"table-only", "", "write the table from the runs done so far, running nothing"},
  };
}

constexpr const char* kSummary =
    "Expands a sweep file (see experiments/sweeps/) into runs, one per experiment,\n"
    "estimator, variant, grid point and seed, and runs each as `opf run` across the\n"
    "machine's cores. Runs whose result files exist are skipped, so a stopped sweep\n"
    "resumes. Writes <out>/<name>.csv, one row per run with its parameters and errors,\n"
    "and prints the errors per configuration (mean +- std over seeds). Each run keeps\n"
    "its settings.yaml, log.txt and `opf run` outputs under <out>/<experiment>/...\n"
    "Exits 1 when a run failed (its log is named). --plan prints the runs as JSON\n"
    "for workflow engines (workflow/Snakefile runs the same sweep on Snakemake).";

// Per experiment, what `opf run --preset P --config <the run's settings.yaml>` starts from before
// the run's variant and grid point: the preset (under `paper`, then the experiment's
// paper_preset_config), the sweep's config, and the experiment's camera where those place none.
std::vector<std::pair<std::string, EstimatorSettings>> starting_settings(
    const experiments::SweepSpec& spec, const std::string& preset) {
  std::vector<std::pair<std::string, EstimatorSettings>> settings;
  for (const std::filesystem::path& file : spec.experiments) {
    const sim::ExperimentConfig config = sim::load_experiment(file);
    EstimatorSettings each = preset_settings(preset, config.paper_preset_config);
    if (spec.config) each = load_estimator_settings(*spec.config, each);
    settings.emplace_back(config.name, experiments::with_experiment_camera(each, config));
  }
  return settings;
}

// The runs execute this very program, even when its file is rebuilt or deleted during the sweep
// (the kernel keeps the running binary's inode for /proc/self/exe).
const std::filesystem::path kThisProgram = "/proc/self/exe";

}  // namespace

CommandHelp sweep_help() {
  return {"sweep SWEEP.yaml", kSummary, specs()};
}

int sweep_command(const std::vector<std::string>& raw) {
  const auto option_specs = specs();
  const auto [options, positional] = split_positional(raw, option_specs);
  const Arguments args(options, option_specs);
  if (args.help()) {
    std::cout << usage(sweep_help());
    return 0;
  }
  if (positional.size() != 1) throw UsageError{"expected one sweep file"};
  const std::string preset = args.get("preset").value_or("default");
  preset_settings(preset);  // an unknown preset fails before anything runs
  const experiments::SweepSpec spec = experiments::load_sweep(positional[0]);
  // A preset's runs go to their own directory: resuming must not mix them with the defaults'.
  const std::string default_name = preset == "default" ? spec.name : spec.name + "-" + preset;
  const std::filesystem::path out = args.get("out").value_or(
      (std::filesystem::path("results") / "sweeps" / default_name).string());
  require_folder({"--out", out.string()});
  const std::size_t jobs =
      args.get_count("jobs").value_or(std::max(1u, std::thread::hardware_concurrency()));
  if (jobs == 0) throw UsageError{"option '--jobs' must be at least 1"};
  std::vector<experiments::SweepRun> runs = experiments::expand_sweep(spec);
  if (preset != "default")
    for (auto& run : runs) run.preset = preset;

  if (args.has("plan")) {
    experiments::write_sweep_plan(std::cout, spec, runs, out);
    return 0;
  }
  if (args.has("list")) {
    for (const auto& run : runs)
      std::cout << (std::filesystem::exists(out / run.result_file()) ? "done     " : "pending  ")
                << run.directory.string() << "\n";
    std::cout << runs.size() << " runs\n";
    return 0;
  }
  experiments::SweepExecution execution;
  if (args.has("table-only")) {
    if (!std::filesystem::is_directory(out))
      throw UsageError{"option '--table-only': no sweep has run in " + out.string() +
                       " (no such directory): run the sweep first, or name its --out"};
    for (const auto& run : runs)
      execution.skipped += std::filesystem::exists(out / run.result_file());
  } else {
    std::cerr << spec.name << ": " << runs.size() << " runs, " << jobs << " at a time, in "
              << out.string() << "\n";
    execution = experiments::execute_sweep(runs, out, kThisProgram, jobs, std::cerr,
                                           isatty(STDERR_FILENO) != 0);
  }
  const std::filesystem::path table = out / (spec.name + ".csv");
  const std::size_t ok = experiments::write_sweep_table(spec, runs, out, table);
  // Beside the table, how it was made: the settings each experiment's runs start from, before
  // their variant and grid point (each run's own summary.json carries its full settings).
  write_file_atomically(out / (spec.name + ".provenance.json"), [&](std::ostream& os) {
    os << provenance_json(command_line("sweep", raw), starting_settings(spec, preset)) << "\n";
  });
  experiments::print_sweep_summary(std::cout, table);
  std::cout << "\n"
            << ok << " of " << runs.size() << " runs in " << table.string() << " ("
            << execution.skipped << " were done before, " << execution.completed << " ran now)\n";
  if (args.has("table-only")) return ok == runs.size() ? 0 : 1;
  if (execution.failed.empty()) return 0;
  std::cerr << execution.failed.size() << " runs failed; their logs:\n";
  for (const auto& dir : execution.failed)
    std::cerr << "  " << (out / dir / "log.txt").string() << "\n";
  return 1;
}

}  // namespace opf::cli
