#include "evaluate_command.h"

#include "arguments.h"
#include "core/error_accumulator.h"
#include "core/metrics.h"
#include "core/tracker.h"
#include "estimator_arguments.h"
#include "estimators/registry.h"
#include "io/measurement_log.h"
#include "particles/random.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace opf::cli {
namespace {

std::vector<OptionSpec> specs() {
  std::vector<OptionSpec> s = {
      {"in", "LOG.csv", "measurement log (default: the bundled experiments/data/example_log.csv)"},
      {"truth", "TRUTH.csv", "ground truth, same columns, every object at every frame"},
      {"estimators", "A,B,...", "estimators to compare (default: all registered)"},
      {"seeds", "N", "runs per estimator, seeds derived from --seed (default 5)"},
  };
  for (auto& spec : estimator_option_specs()) s.push_back(std::move(spec));
  return s;
}

constexpr const char* kSummary =
    "Replays a measurement log through each estimator over N seeds and prints, per estimator,\n"
    "the mean +- std over seeds of the per-run mean errors against the ground truth: translation\n"
    "(m), rotation as the paper's Euler-angle difference and as the geodesic angle (rad), and\n"
    "translation over the frames the object was unobserved. A second table splits the errors\n"
    "into unobserved (hidden) and measured (visible) frames and reports how honest the position\n"
    "covariance was while hidden: the share of hidden frames within 2 sqrt(trace) of it\n"
    "(coverage) and the median error / sqrt(trace).";

using TruthTable = std::map<std::pair<double, std::string>, mrpt::poses::CPose3D>;

TruthTable truth_table(const MeasurementLog& truth) {
  TruthTable table;
  for (const Frame& frame : truth.frames)
    for (const Detection& d : frame.detections)
      table.emplace(std::make_pair(frame.t, d.object), d.pose);
  return table;
}

RunErrors run_once(const MeasurementLog& log, const TruthTable& truth, const std::string& name,
                   const EstimatorSettings& settings, std::uint64_t seed, std::size_t threads,
                   const std::string& truth_path) {
  Tracker tracker(make_estimator_factory(name, settings), seed, threads);
  ErrorAccumulator errors;
  for (const Frame& frame : log.frames) {
    for (const Estimate& estimate : tracker.step(frame)) {
      const auto it = truth.find({frame.t, estimate.object});
      if (it == truth.end()) {
        std::ostringstream msg;
        msg << truth_path << ": no ground truth for object '" << estimate.object
            << "' at t = " << frame.t;
        throw std::runtime_error(msg.str());
      }
      errors.add(estimate, it->second);
    }
  }
  return errors.result();
}

std::string cell(const MeanStd& value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.5f +- %.5f", value.mean, value.std);
  return buffer;
}

}  // namespace

int evaluate_command(const std::vector<std::string>& raw) {
  const auto option_specs = specs();
  const Arguments args(raw, option_specs);
  if (args.help()) {
    std::cout << usage("evaluate", kSummary, option_specs);
    return 0;
  }
  const std::string data = std::string(OPF_SOURCE_DIR) + "/experiments/data/";
  const std::string example = data + "example_log.csv";
  const std::string in = args.get("in").value_or(example);
  // The bundled truth belongs to the bundled log only: compared with another log it would score
  // the estimators against the wrong motion.
  std::error_code ignored;
  if (!args.has("truth") && !std::filesystem::equivalent(in, example, ignored))
    throw UsageError{"option '--truth' is required with --in " + in +
                     " (the bundled example_truth.csv belongs to the bundled example log only)"};
  const std::string truth_path = args.get("truth").value_or(data + "example_truth.csv");
  const auto names =
      args.has("estimators") ? split_list(*args.get("estimators")) : estimator_names();
  // Every name is checked before the first run, not when its turn comes.
  const std::vector<std::string> known = estimator_names();
  for (const std::string& name : names)
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      throw UsageError{"option '--estimators': unknown estimator '" + name + "' (known: " + list +
                       ")"};
    }
  const std::size_t seeds = args.get_count("seeds").value_or(5);
  if (seeds == 0) throw UsageError{"option '--seeds' must be at least 1"};
  const EstimatorSettings settings = settings_from(args);
  require_camera_for_line_of_sight(settings);
  const std::uint64_t base_seed = seed_from(args);
  const std::size_t threads = threads_from(args);

  const MeasurementLog log = read_measurement_log(in);
  const TruthTable truth = truth_table(read_measurement_log(truth_path));

  std::printf("opf evaluate: %s, %zu frames, %zu objects, %zu seeds, %zu + %zu particles\n\n",
              in.c_str(), log.frames.size(), log.objects.size(), seeds,
              settings.pf.translation_particles, settings.pf.rotation_particles);
  std::printf("%-10s %-22s %-22s %-22s %-22s\n", "estimator", "translation [m]",
              "rotation paper [rad]", "rotation geodesic", "transl. unobserved [m]");
  struct Row {
    std::string name;
    std::vector<double> hidden_translation, hidden_rotation, visible_translation, visible_rotation,
        coverage, normalised;
  };
  std::vector<Row> rows;
  for (const std::string& name : names) {
    std::vector<double> translation, paper, geodesic;
    Row row{name, {}, {}, {}, {}, {}, {}};
    for (std::size_t k = 0; k < seeds; ++k) {
      const RunErrors r =
          run_once(log, truth, name, settings, derive_seed(base_seed, k), threads, truth_path);
      translation.push_back(r.translation);
      paper.push_back(r.rotation_paper);
      geodesic.push_back(r.rotation_geodesic);
      row.hidden_translation.push_back(r.translation_unobserved);
      row.hidden_rotation.push_back(r.rotation_unobserved);
      row.visible_translation.push_back(r.translation_visible);
      row.visible_rotation.push_back(r.rotation_visible);
      row.coverage.push_back(r.coverage_unobserved);
      row.normalised.push_back(r.normalised_error_unobserved);
    }
    std::printf("%-10s %-22s %-22s %-22s %-22s\n", name.c_str(),
                cell(mean_std(translation)).c_str(), cell(mean_std(paper)).c_str(),
                cell(mean_std(geodesic)).c_str(), cell(mean_std(row.hidden_translation)).c_str());
    std::fflush(stdout);
    rows.push_back(std::move(row));
  }
  // The same runs split by whether the object was measured, and how honest the reported
  // position covariance was while it was not.
  std::printf("\n%-10s %-13s %-13s %-13s %-13s %-10s %-10s\n", "estimator", "hidden [m]",
              "hidden [rad]", "visible [m]", "visible [rad]", "coverage", "err/sd");
  for (const Row& row : rows) {
    std::printf("%-10s %-13.5f %-13.5f %-13.5f %-13.5f %-10.3f %-10.3f\n", row.name.c_str(),
                mean_std(row.hidden_translation).mean, mean_std(row.hidden_rotation).mean,
                mean_std(row.visible_translation).mean, mean_std(row.visible_rotation).mean,
                mean_std(row.coverage).mean, mean_std(row.normalised).mean);
  }
  std::printf(
      "\ncoverage: share of unobserved frames whose translation error is within 2 sqrt(trace) of "
      "the estimate's\nposition covariance; err/sd: median of error / sqrt(trace) over them (means "
      "over seeds)\n");
  return 0;
}

}  // namespace opf::cli
