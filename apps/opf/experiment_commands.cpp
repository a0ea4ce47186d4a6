#include "experiment_commands.h"

#include "arguments.h"
#include "command_help.h"
#include "drivers/closed_loop_run.h"
#include "drivers/data_directory.h"
#include "drivers/figures.h"
#include "drivers/measurement_export.h"
#include "drivers/observe_experiment.h"
#include "drivers/results_files.h"
#include "estimator_arguments.h"
#include "opf/core/random.h"
#include "opf/estimators/registry.h"
#include "opf/io/atomic_file.h"
#include "opf/io/estimator_settings_yaml.h"
#include "output_paths.h"
#include "provenance.h"

#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

namespace opf::cli {
namespace {

std::vector<OptionSpec> specs(bool reproduce) {
  std::vector<OptionSpec> s = {
      {"estimators", "A,B,...", "estimators to compare (default: all registered)"},
      {"seeds", "N",
       "runs per estimator, each with its own sensor noise (default 5; 100000 runs at most)"},
      {"out", "DIR",
       reproduce ? "where results go (default: results)"
                 : "where results go (default: results/<experiment name>)"},
  };
  if (!reproduce) {
    s.push_back({"first-seed", "K",
                 "seed index of the first run (default 0): seeds K..K+N-1 are the same runs as in "
                 "a longer run with the same --seed"});
    s.push_back({"frames", "N", "track the first N frames only (default: all the file's)"});
    s.push_back({"no-figures", "", "write the CSVs and summary.json, not the figures"});
    s.push_back({"measurements", "",
                 "also write each seed's detections as a measurement log "
                 "(<name>_measurements_seed<K>.csv, for opf track or another tracker) and the "
                 "truth (<name>_truth.csv, for opf evaluate --truth), with the settings with "
                 "which opf track reproduces the runs (<name>_settings.yaml); open-loop "
                 "experiments"});
  }
  s.push_back({"quiet", "", "no progress line (it is drawn only on a terminal anyway)"});
  for (auto& spec : estimator_option_specs()) s.push_back(std::move(spec));
  return s;
}

// How `opf track` reproduces the runs on each seed's measurement log: with the settings in
// `settings_file` and the run's seed for that log's index.
std::vector<std::string> replay_lines(const std::filesystem::path& settings_file,
                                      const std::vector<std::filesystem::path>& logs,
                                      std::uint64_t seed, std::size_t first_seed) {
  std::vector<std::string> lines = {"opf track --in LOG --config " + settings_file.string() +
                                    " --estimator E --seed S reproduces this run's estimates of E "
                                    "on LOG:"};
  for (std::size_t i = 0; i + 1 < logs.size(); ++i)  // the truth is last
    lines.push_back("  " + logs[i].filename().string() + ": --seed " +
                    std::to_string(derive_seed(seed, first_seed + i)));
  return lines;
}

// What `opf run` and `opf reproduce` were asked for, checked before any rendering.
struct RunRequest {
  std::vector<std::string> names;
  std::size_t seeds = 0;
  std::uint64_t seed = 0;
  std::size_t threads = 1;
  std::size_t first_seed = 0;
  std::optional<std::size_t> frames;
  bool with_figures = true;
  bool with_measurements = false;
  experiments::Progress progress;
};

RunRequest run_request(const Arguments& args, std::size_t experiment_count) {
  RunRequest r;
  r.names = args.has("estimators") ? split_list(*args.get("estimators")) : estimator_names();
  require_known_estimators("estimators", r.names);
  r.seeds = seeds_from(args, r.names.size() * experiment_count);
  settings_from(args);  // a bad --config fails here too
  r.seed = seed_from(args);
  r.threads = threads_from(args);
  r.first_seed = args.get_count("first-seed").value_or(0);
  r.frames = args.get_count("frames");
  if (r.frames && *r.frames == 0) throw UsageError{"option '--frames' must be at least 1"};
  r.with_figures = !args.has("no-figures");
  r.with_measurements = args.has("measurements");
  // A progress line redrawn in place: on a terminal only, so that no escape codes reach a file.
  if (!args.has("quiet") && isatty(STDERR_FILENO) != 0)
    r.progress = [](const std::string& line) { std::cerr << "\r\033[K" << line << std::flush; };
  else
    r.progress = [](const std::string&) {};
  return r;
}

// What the experiments' runs leave to write and print.
struct RunOutputs {
  std::vector<experiments::ExperimentResults> all;
  std::vector<std::pair<std::string, EstimatorSettings>> effective;  // per experiment
  std::vector<std::filesystem::path> figures;
  std::size_t logs = 0;
  std::vector<std::string> replays;
};

void run_experiment(const std::string& path, const Arguments& args, const RunRequest& r,
                    const std::filesystem::path& out, RunOutputs& o) {
  sim::ExperimentConfig config = sim::load_experiment(path);
  if (r.frames) {
    if (*r.frames > static_cast<std::size_t>(config.frames))
      throw UsageError{"option '--frames': " + path + " has " + std::to_string(config.frames) +
                       " frames"};
    config.frames = static_cast<int>(*r.frames);
  }
  const EstimatorSettings settings =
      experiments::with_experiment_camera(settings_from(args, config.paper_preset_config), config);
  o.effective.emplace_back(config.name, settings);
  if (config.closed_loop && r.with_measurements)
    throw UsageError{"option '--measurements': " + path +
                     " is a closed loop, whose detections depend on the estimator driving the "
                     "robot; the measurement logs are written for open-loop experiments"};
  experiments::Observation observation;
  if (config.closed_loop) {
    o.all.push_back(experiments::run_closed_loop(config, r.names, settings, r.seeds, r.seed,
                                                 r.progress, r.threads, r.first_seed));
  } else {
    observation = experiments::observe_experiment(config, r.progress);
    o.all.push_back(experiments::run_open_loop(config, observation, r.names, settings, r.seeds,
                                               r.seed, r.progress, r.threads, r.first_seed));
  }
  if (r.with_measurements) {
    const auto written = experiments::write_measurement_logs(out, config, observation, r.seed,
                                                             r.first_seed, r.seeds);
    o.logs += written.size();
    const std::filesystem::path settings_file = out / (config.name + "_settings.yaml");
    write_file_atomically(settings_file,
                          [&](std::ostream& file) { file << dump_estimator_settings(settings); });
    for (auto& line : replay_lines(settings_file, written, r.seed, r.first_seed))
      o.replays.push_back(std::move(line));
  }
  if (r.with_figures)
    for (auto& figure : experiments::write_figures(out, config, observation, o.all.back()))
      o.figures.push_back(std::move(figure));
}

void write_results(const RunOutputs& o, const RunRequest& r, const std::string& command,
                   const std::filesystem::path& out) {
  // The runs CSV last: its presence tells a sweep that this run finished.
  for (const auto& results : o.all)
    experiments::write_records_csv(out / (results.experiment + "_frames.csv"), results);
  experiments::write_summary_json(out / "summary.json", o.all,
                                  provenance_json(command, o.effective, 2));
  for (const auto& results : o.all)
    experiments::write_runs_csv(out / (results.experiment + "_runs.csv"), results);
  experiments::print_results_table(std::cout, o.all);
  std::cout << "\nper-frame and per-run results, summary.json, " << o.figures.size()
            << " figure files (PNG, SVG)";
  if (r.with_measurements) std::cout << ", " << o.logs << " measurement logs and their settings";
  std::cout << " written to " << out.string() << "\n";
  for (const std::string& line : o.replays) std::cout << line << '\n';
}

int run_experiments(const std::vector<std::string>& paths, const Arguments& args,
                    const std::string& command, const std::filesystem::path& out) {
  const RunRequest request = run_request(args, paths.size());
  require_folder({"--out", out.string()});
  std::filesystem::create_directories(out);
  RunOutputs outputs;
  for (const std::string& path : paths) run_experiment(path, args, request, out, outputs);
  request.progress("");  // clears the line
  write_results(outputs, request, command, out);
  return 0;
}

constexpr const char* kRunSummary =
    "Runs one experiment file (see experiments/general_op.yaml): renders the\n"
    "scripted scene with the simulated camera, then runs every estimator over\n"
    "the seeds on the same measurement stream and prints the errors of the\n"
    "experiment's objects of interest.";

constexpr const char* kReproduceSummary =
    "Reproduces the paper's simulated experiments (Table I: general_op and\n"
    "sugar_drop) and its baseball throw (motion capture, 0.5 s dropout) on the\n"
    "bundled experiment files: every estimator, 5 seeds, 5000 + 5000 particles\n"
    "by default. Prints the table with the paper's numbers beside ours and writes\n"
    "per-frame CSVs and summary.json.";

}  // namespace

CommandHelp run_help() {
  return {"run EXPERIMENT.yaml", kRunSummary, specs(false)};
}
CommandHelp reproduce_help() {
  return {"reproduce", kReproduceSummary, specs(true)};
}

int run_command(const std::vector<std::string>& raw) {
  const auto option_specs = specs(false);
  const auto [options, positional] = split_positional(raw, option_specs);
  const Arguments args(options, option_specs);
  if (args.help()) {
    std::cout << usage(run_help());
    return 0;
  }
  if (positional.size() != 1) throw UsageError{"expected one experiment file"};
  const std::string name = std::filesystem::path(positional[0]).stem().string();
  return run_experiments(
      positional, args, command_line("run", raw),
      args.get("out").value_or((std::filesystem::path("results") / name).string()));
}

int reproduce_command(const std::vector<std::string>& raw) {
  const auto option_specs = specs(true);
  const Arguments args(raw, option_specs);
  if (args.help()) {
    std::cout << usage(reproduce_help());
    return 0;
  }
  const std::string dir = experiments::bundled_experiments().string() + "/";
  return run_experiments({dir + "general_op.yaml", dir + "sugar_drop.yaml", dir + "baseball.yaml"},
                         args, command_line("reproduce", raw), args.get("out").value_or("results"));
}

}  // namespace opf::cli
