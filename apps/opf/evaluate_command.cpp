#include "evaluate_command.h"

#include "arguments.h"
#include "command_help.h"
#include "drivers/data_directory.h"
#include "estimator_arguments.h"
#include "log_arguments.h"
#include "opf/core/error_accumulator.h"
#include "opf/core/gap_errors.h"
#include "opf/core/ground_truth.h"
#include "opf/core/metrics.h"
#include "opf/core/random.h"
#include "opf/core/tracker.h"
#include "opf/estimators/registry.h"
#include "opf/io/atomic_file.h"
#include "opf/io/csv.h"
#include "opf/io/json_text.h"
#include "opf/io/measurement_log.h"
#include "opf/io/unsized_log_note.h"
#include "output_paths.h"
#include "provenance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace opf::cli {
namespace {

/// Times this close count as equal when a log's frames group equal times only.
constexpr double kExactTimeTolerance = 1e-9;

std::vector<OptionSpec> specs() {
  std::vector<OptionSpec> s = {
      {"in", "LOG.csv", "measurement log (default: the bundled experiments/data/example_log.csv)"},
      {"truth", "TRUTH.csv",
       "ground truth: a log in the same units and columns with every object, at its own times "
       "(interpolated at each estimate's)"},
      {"estimators", "A,B,...", "estimators to compare (default: all registered)"},
      {"seeds", "N",
       "runs per estimator, seeds derived from --seed (default 5; 100000 runs at most)"},
      {"out", "FILE.csv|FILE.json",
       "also write the tables: a row per estimator (csv), or with the provenance (json)"},
      {"hidden-profile", "FILE.csv",
       "also write the error against time hidden: a row per estimator and 0.1 s bin"},
      {"gap-errors", "FILE.csv",
       "also write the errors per gap of the log: a row per estimator, object and gap"},
      {"alert-distance", "M",
       "the error the alert should announce, for its precision and recall (default 0.1 m)"},
  };
  for (auto& spec : log_option_specs()) s.push_back(std::move(spec));
  for (auto& spec : estimator_option_specs()) s.push_back(std::move(spec));
  return s;
}

constexpr const char* kSummary =
    "Replays a measurement log through each estimator over N seeds and prints, per estimator,\n"
    "the mean +- sample std (n - 1) over seeds of the per-run mean errors against the ground\n"
    "truth: translation (m), rotation as the paper's Euler-angle difference and as the geodesic\n"
    "angle (rad), and translation over the frames the object was unobserved. A second table\n"
    "splits the errors into unobserved (hidden) and measured (visible) frames and reports how\n"
    "honest the position covariance was while hidden: the share of hidden frames within\n"
    "2 sqrt(trace) of it (coverage) and the median error / sqrt(trace). A third table gives the\n"
    "calibration by the normalised estimation error squared (NEES / 3 and the share inside the\n"
    "95% ellipsoid, of position and orientation), reacquisition after gaps and the alert's\n"
    "precision and recall (definitions: docs/metrics.md).";

/// An estimator's further hypotheses (the OPF's: carried or left, several occluders) over the
/// hidden frames of a run: in how many the object had more than one, and the translation error of
/// the hypothesis nearest the truth against the main one's (sums over the hidden frames).
struct HypothesisTally {
  std::size_t hidden_frames = 0;
  std::size_t with_more = 0;
  double main = 0.0;
  double nearest = 0.0;

  /// The main estimate, its translation error against `truth`, and the estimator's further
  /// hypotheses after the step.
  void add(const Estimate& estimate, double main_error, const std::vector<Estimate>& hypotheses,
           const mrpt::poses::CPose3D& truth) {
    if (estimate.mode == EstimateMode::kMeasured) return;
    double nearest_error = main_error;
    bool more = false;
    for (const Estimate& h : hypotheses) {
      if (h.object != estimate.object) continue;
      more = true;
      nearest_error = std::min(nearest_error, translation_error(h.pose.mean, truth));
    }
    ++hidden_frames;
    with_more += more;
    main += main_error;
    nearest += nearest_error;
  }

  HypothesisTally& operator+=(const HypothesisTally& other) {
    hidden_frames += other.hidden_frames;
    with_more += other.with_more;
    main += other.main;
    nearest += other.nearest;
    return *this;
  }
};

/// What the runs leave to say after the tables: how many estimates of filled frames had no truth
/// to compare with (the most of any run), and whether the occluder module took an object in a log
/// that states no sizes (unsized_log_note).
struct RunNotes {
  std::size_t unscored = 0;
  bool unsized = false;

  void add(const RunNotes& run) {
    unscored = std::max(unscored, run.unscored);
    unsized = unsized || run.unsized;
  }
};

/// The errors of one run, and its notes.
struct ScoredRun {
  RunErrors errors;
  std::vector<GapError> gaps;
  HypothesisTally hypotheses;
  RunNotes notes;
};

ScoredRun run_once(const MeasurementLog& log, const GroundTruth& truth, const std::string& name,
                   const EstimatorSettings& settings, std::uint64_t seed, std::size_t threads,
                   const std::string& truth_path, double alert_distance) {
  Tracker tracker(make_estimator_factory(name, settings), seed, threads);
  ErrorAccumulator errors(settings.opf.feedback.epsilon_safe, alert_distance);
  GapErrors gaps;
  UnsizedLogWatch unsized;
  ScoredRun run;
  for (const Frame& frame : log.frames) {
    for (const Detection& detection : frame.detections) unsized.saw(detection);
    for (const Estimate& estimate : tracker.step(frame)) {
      unsized.saw(estimate);
      const std::optional<mrpt::poses::CPose3D> pose = truth.at(estimate.object, frame.t);
      if (!pose && frame.filled) {
        ++run.notes.unscored;  // a frame the log never had: no truth there is no fault
        continue;
      }
      if (!pose)
        throw std::runtime_error(truth_path + ": " + truth.missing(estimate.object, frame.t));
      errors.add(estimate, *pose);
      const double translation = translation_error(estimate.pose.mean, *pose);
      gaps.add(estimate.object, frame.t, frame.find(estimate.object) != nullptr, translation,
               rotation_error_geodesic(estimate.pose.mean, *pose));
      run.hypotheses.add(estimate, translation, tracker.hypotheses(), *pose);
    }
    for (const Estimate& hypothesis : tracker.hypotheses()) unsized.saw(hypothesis);
  }
  run.notes.unsized = unsized.note_due();
  run.errors = errors.result();
  run.gaps = gaps.gaps();
  return run;
}

/// Every estimate a run writes is scored: each object at every frame of the log from its first
/// detection on (filled frames excepted). A truth that misses one is refused before any run, not
/// after the first.
void require_truth_for_every_estimate(const MeasurementLog& log, const GroundTruth& truth,
                                      const std::string& truth_path) {
  std::set<std::string> started;
  for (const Frame& frame : log.frames) {
    for (const Detection& d : frame.detections) started.insert(d.object);
    if (frame.filled) continue;
    for (const std::string& object : started)
      if (!truth.at(object, frame.t))
        throw std::runtime_error(truth_path + ": " + truth.missing(object, frame.t));
  }
}

/// A JSON number, null when not finite (a seed with no hidden frame).
std::string json_number(double value) {
  return std::isfinite(value) ? csv::format_double(value) : "null";
}

/// Mean and sample std over the seeds where the value is defined (a seed without an alert has no
/// alert precision); NaN when none is.
MeanStd mean_std_defined(const std::vector<double>& values) {
  std::vector<double> defined;
  for (double v : values)
    if (!std::isnan(v)) defined.push_back(v);
  if (defined.empty()) return {std::nan(""), std::nan("")};
  return mean_std(defined);
}

// Over one seed there is no spread to print: the mean alone.
std::string cell(const MeanStd& value) {
  char buffer[64];
  if (value.has_spread())
    std::snprintf(buffer, sizeof buffer, "%.5f +- %.5f", value.mean, value.std);
  else
    std::snprintf(buffer, sizeof buffer, "%.5f", value.mean);
  return buffer;
}

/// One estimator's errors, one value per seed.
struct Row {
  std::string name;
  std::vector<double> translation, paper, geodesic, hidden_translation, hidden_rotation,
      visible_translation, visible_rotation, coverage, normalised, nees_translation, nees_rotation,
      inside95_translation, inside95_rotation, reacquisition_error, reacquisition_frames,
      alert_precision, alert_recall, nearest_hidden_translation;
  /// Further hypotheses over every seed.
  HypothesisTally hypotheses;
  /// Error against time hidden over every seed: frames and error sums per 0.1 s bin.
  std::vector<HiddenErrorBin> profile;
  /// The log's gaps, by start and object: frames and error sums over every seed.
  std::map<std::pair<double, std::string>, GapError> gaps;

  void add(const ScoredRun& run) {
    for (const GapError& gap : run.gaps) {
      auto [it, fresh] = gaps.try_emplace({gap.start, gap.object}, gap);
      if (fresh) continue;
      it->second.frames += gap.frames;
      it->second.translation += gap.translation;
      it->second.rotation += gap.rotation;
    }
    const HypothesisTally& h = run.hypotheses;
    nearest_hidden_translation.push_back(
        h.hidden_frames ? h.nearest / static_cast<double>(h.hidden_frames) : std::nan(""));
    hypotheses += h;
    add(run.errors);
  }

  void add(const RunErrors& r) {
    translation.push_back(r.translation);
    paper.push_back(r.rotation_paper);
    geodesic.push_back(r.rotation_geodesic);
    hidden_translation.push_back(r.translation_unobserved);
    hidden_rotation.push_back(r.rotation_unobserved);
    visible_translation.push_back(r.translation_visible);
    visible_rotation.push_back(r.rotation_visible);
    coverage.push_back(r.coverage_unobserved);
    normalised.push_back(r.normalised_error_unobserved);
    nees_translation.push_back(r.nees_translation);
    nees_rotation.push_back(r.nees_rotation);
    inside95_translation.push_back(r.inside95_translation);
    inside95_rotation.push_back(r.inside95_rotation);
    reacquisition_error.push_back(r.reacquisition.first_error);
    reacquisition_frames.push_back(r.reacquisition.frames_to_settle);
    alert_precision.push_back(r.alert_precision);
    alert_recall.push_back(r.alert_recall);
    if (profile.size() < r.hidden_profile.size()) profile.resize(r.hidden_profile.size());
    for (std::size_t k = 0; k < r.hidden_profile.size(); ++k) {
      const HiddenErrorBin& bin = r.hidden_profile[k];
      profile[k].frames += bin.frames;
      profile[k].translation += bin.translation * static_cast<double>(bin.frames);
      profile[k].rotation += bin.rotation * static_cast<double>(bin.frames);
    }
  }
};

/// The columns of --out, each a statistic over seeds of one error of a Row.
struct Column {
  const char* name;
  std::vector<double> Row::*values;
};
constexpr Column kColumns[] = {
    {"translation", &Row::translation},
    {"rotation_paper", &Row::paper},
    {"rotation_geodesic", &Row::geodesic},
    {"hidden_translation", &Row::hidden_translation},
    {"hidden_rotation", &Row::hidden_rotation},
    {"visible_translation", &Row::visible_translation},
    {"visible_rotation", &Row::visible_rotation},
    {"coverage", &Row::coverage},
    {"error_over_sd", &Row::normalised},
    {"nees_translation", &Row::nees_translation},
    {"nees_rotation", &Row::nees_rotation},
    {"inside95_translation", &Row::inside95_translation},
    {"inside95_rotation", &Row::inside95_rotation},
    {"reacquisition_error", &Row::reacquisition_error},
    {"reacquisition_frames", &Row::reacquisition_frames},
    {"alert_precision", &Row::alert_precision},
    {"alert_recall", &Row::alert_recall},
    {"nearest_hidden_translation", &Row::nearest_hidden_translation},
};

/// The error against time hidden: a row per estimator and non-empty 0.1 s bin, pooled over seeds.
void write_hidden_profile(const std::filesystem::path& path, const std::vector<Row>& rows) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "estimator,time_hidden_from,time_hidden_to,frames,hidden_translation,hidden_rotation\n";
    for (const Row& row : rows)
      for (std::size_t k = 0; k < row.profile.size(); ++k) {
        const HiddenErrorBin& bin = row.profile[k];
        if (bin.frames == 0) continue;
        const auto n = static_cast<double>(bin.frames);
        out << csv::quote_if_needed(row.name) << ','
            << csv::format_double(static_cast<double>(k) * HiddenErrorProfile::kBinWidth) << ','
            << csv::format_double(static_cast<double>(k + 1) * HiddenErrorProfile::kBinWidth) << ','
            << bin.frames << ',' << csv::format_double(bin.translation / n) << ','
            << csv::format_double(bin.rotation / n) << '\n';
      }
  });
}

/// The errors per gap of the log: a row per estimator, object and gap, pooled over seeds.
void write_gap_errors(const std::filesystem::path& path, const std::vector<Row>& rows) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "estimator,object,gap_start,gap_end,frames,hidden_translation,hidden_rotation\n";
    for (const Row& row : rows)
      for (const auto& [key, gap] : row.gaps) {
        const auto n = static_cast<double>(gap.frames);
        out << csv::quote_if_needed(row.name) << ',' << csv::quote_if_needed(gap.object) << ','
            << csv::format_double(gap.start) << ',' << csv::format_double(gap.end) << ','
            << gap.frames << ',' << csv::format_double(gap.translation / n) << ','
            << csv::format_double(gap.rotation / n) << '\n';
      }
  });
}

/// The tables as a file: .csv (a row per estimator, mean and std over seeds per error) or .json
/// (the same with the provenance).
void write_evaluation(const std::filesystem::path& path, const std::vector<Row>& rows,
                      const std::string& provenance) {
  const bool json = path.extension() == ".json";
  write_file_atomically(path, [&](std::ostream& out) {
    if (!json) {
      out << "estimator";
      for (const Column& c : kColumns) out << ',' << c.name << ',' << c.name << "_std";
      out << '\n';
      for (const Row& row : rows) {
        out << csv::quote_if_needed(row.name);
        for (const Column& c : kColumns) {
          const MeanStd m = mean_std_defined(row.*c.values);
          out << ',' << csv::format_double(m.mean) << ',' << csv::format_double(m.std);
        }
        out << '\n';
      }
      return;
    }
    out << "{\n  \"provenance\": " << provenance << ",\n  \"estimators\": {\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
      out << "    " << json_string(rows[i].name) << ": {\n";
      out << "      \"seeds\": " << rows[i].translation.size();
      for (const Column& c : kColumns) {
        const MeanStd m = mean_std_defined(rows[i].*c.values);
        out << ",\n      \"" << c.name << "\": {\"mean\": " << json_number(m.mean)
            << ", \"std\": " << json_number(m.std) << "}";
      }
      out << "\n    }" << (i + 1 < rows.size() ? ",\n" : "\n");
    }
    out << "  }\n}\n";
  });
}

/// For the estimators that kept further hypotheses: in how many hidden frames, and how near the
/// nearest came (as `opf run` says it of an experiment).
void print_hypotheses(const std::vector<Row>& rows) {
  bool first = true;
  for (const Row& row : rows) {
    const HypothesisTally& h = row.hypotheses;
    if (h.with_more == 0) continue;
    if (std::exchange(first, false)) std::printf("\n");
    const auto n = static_cast<double>(h.hidden_frames);
    std::printf(
        "%-10s more than one hypothesis in %zu of %zu hidden frames; hidden error of the one "
        "nearest the truth %.5f m (the main one's %.5f m)\n",
        row.name.c_str(), h.with_more, h.hidden_frames, h.nearest / n, h.main / n);
  }
}

/// The third table: calibration on hidden frames, reacquisition and the alert as a detector.
void print_calibration(const std::vector<Row>& rows, double alert_distance) {
  std::printf("\n%-10s %-10s %-10s %-10s %-10s %-12s %-12s %-10s %-10s\n", "estimator", "NEES/3 t",
              "in95 t", "NEES/3 r", "in95 r", "reacq. [m]", "settle [fr]", "alert P", "alert R");
  for (const Row& row : rows)
    std::printf(
        "%-10s %-10.3g %-10.3f %-10.3g %-10.3f %-12.5f %-12.2f %-10.3f %-10.3f\n", row.name.c_str(),
        mean_std_defined(row.nees_translation).mean,
        mean_std_defined(row.inside95_translation).mean, mean_std_defined(row.nees_rotation).mean,
        mean_std_defined(row.inside95_rotation).mean,
        mean_std_defined(row.reacquisition_error).mean,
        mean_std_defined(row.reacquisition_frames).mean, mean_std_defined(row.alert_precision).mean,
        mean_std_defined(row.alert_recall).mean);
  std::printf(
      "\nNEES/3: mean normalised estimation error squared over hidden frames, by dimension "
      "(1 calibrated,\n< 1 cautious, > 1 over-confident); in95: share of hidden frames inside the "
      "95%% ellipsoid;\nreacq.: error at the first measured frame after a gap; settle: frames "
      "until within 2x the visible\nerror; alert P/R: precision and recall of the alert against "
      "an error above %g m\n",
      alert_distance);
}

/// What a command line asks evaluate to do, checked before anything is read.
struct EvaluateRequest {
  std::string in;
  std::string truth_path;
  std::vector<std::string> names;
  std::size_t seeds = 5;
  EstimatorSettings settings;
  std::uint64_t base_seed = 0;
  std::size_t threads = 1;
  double alert_distance = ErrorAccumulator::kDefaultAlertDistance;
};

/// An output path's extension, one of `allowed` (".csv" or ".json"); a usage error otherwise.
void require_extension(const Arguments& args, const char* option,
                       const std::vector<std::string>& allowed, const std::string& expected) {
  const auto path = args.get(option);
  if (!path) return;
  const std::string extension = std::filesystem::path(*path).extension().string();
  if (std::find(allowed.begin(), allowed.end(), extension) == allowed.end())
    throw UsageError{"option '--" + std::string(option) + "': expected a file name ending in " +
                     expected + ", got \"" + *path + "\""};
}

EvaluateRequest evaluate_request(const Arguments& args) {
  EvaluateRequest r;
  const std::string data = (experiments::bundled_experiments() / "data").string() + "/";
  const std::string example = data + "example_log.csv";
  r.in = args.get("in").value_or(example);
  // The bundled truth belongs to the bundled log only: compared with another log it would score
  // the estimators against the wrong motion.
  std::error_code ignored;
  if (!args.has("truth") && !std::filesystem::equivalent(r.in, example, ignored))
    throw UsageError{"option '--truth' is required with --in " + r.in +
                     " (the bundled example_truth.csv belongs to the bundled example log only)"};
  r.truth_path = args.get("truth").value_or(data + "example_truth.csv");
  r.names = args.has("estimators") ? split_list(*args.get("estimators")) : estimator_names();
  require_known_estimators("estimators", r.names);  // all before the first run
  require_extension(args, "out", {".csv", ".json"}, ".csv or .json");
  const std::string config = args.get("config").value_or("");
  for (const char* output : {"out", "hidden-profile", "gap-errors"})
    refuse_output_over_input({"--" + std::string(output), args.get(output).value_or("")},
                             {{"--in", r.in}, {"--truth", r.truth_path}, {"--config", config}});
  refuse_output_over_input({"--hidden-profile", args.get("hidden-profile").value_or("")},
                           {{"--out", args.get("out").value_or("")}});
  refuse_output_over_input({"--gap-errors", args.get("gap-errors").value_or("")},
                           {{"--out", args.get("out").value_or("")},
                            {"--hidden-profile", args.get("hidden-profile").value_or("")}});
  r.seeds = seeds_from(args, r.names.size());
  r.settings = settings_from(args);
  require_camera_for_line_of_sight(r.settings);
  r.base_seed = seed_from(args);
  r.threads = threads_from(args);
  r.alert_distance =
      args.get_number("alert-distance").value_or(ErrorAccumulator::kDefaultAlertDistance);
  if (!(r.alert_distance > 0.0) || !std::isfinite(r.alert_distance))
    throw UsageError{"option '--alert-distance' must be a positive distance in metres"};
  require_extension(args, "hidden-profile", {".csv"}, ".csv");
  require_extension(args, "gap-errors", {".csv"}, ".csv");
  return r;
}

/// The truth, read as the log is (its units and columns) but never filled, at its own times: an
/// estimate takes it interpolated at the estimate's time (core/ground_truth.h), beyond its span
/// a row within the log's frame tolerance.
GroundTruth read_truth(const Arguments& args, const std::string& truth_path,
                       const MeasurementLog& log) {
  LogReadOptions truth_options = log_options_from(args, truth_path);
  // A TUM or ASL truth of the log's one object is that object's, whatever the files are called.
  if (is_one_object_format(truth_options.format) && !args.has("object") && log.objects.size() == 1)
    truth_options.object = log.objects.front();
  truth_options.fill_gaps = false;
  // The rate fills gaps, which a truth never is, except where it times a box file's frame numbers.
  if (!is_frame_numbered_format(truth_options.format)) truth_options.rate.reset();
  const MeasurementLog truth = read_measurement_log(truth_path, truth_options);
  if (!truth.states_orientation && log.states_orientation)  // the log's own note says it else
    note_positions_only("evaluate", truth_path);
  return GroundTruth(truth.frames, std::max(log.report.frame_tolerance, kExactTimeTolerance));
}

/// Every estimator over every seed, each printed as its seeds end: the first table.
std::vector<Row> run_every_estimator(const EvaluateRequest& r, const MeasurementLog& log,
                                     const GroundTruth& truth, RunNotes& notes) {
  if (r.seeds == 1)
    std::printf("errors against the truth, each run's mean over frames (1 seed: no spread)\n");
  else
    std::printf(
        "errors against the truth, each run's mean over frames (mean +- std over %zu seeds)\n",
        r.seeds);
  std::printf("%-10s %-22s %-22s %-22s %-22s\n", "estimator", "translation [m]",
              "rotation paper [rad]", "rotation geodesic", "transl. unobserved [m]");
  std::vector<Row> rows;
  for (const std::string& name : r.names) {
    Row row;
    row.name = name;
    for (std::size_t k = 0; k < r.seeds; ++k) {
      const ScoredRun run = run_once(log, truth, name, r.settings, derive_seed(r.base_seed, k),
                                     r.threads, r.truth_path, r.alert_distance);
      notes.add(run.notes);
      row.add(run);
    }
    std::printf("%-10s %-22s %-22s %-22s %-22s\n", name.c_str(),
                cell(mean_std(row.translation)).c_str(), cell(mean_std(row.paper)).c_str(),
                cell(mean_std(row.geodesic)).c_str(),
                cell(mean_std(row.hidden_translation)).c_str());
    std::fflush(stdout);
    rows.push_back(std::move(row));
  }
  return rows;
}

/// The second table: the same runs split by whether the object was measured, and how honest the
/// reported position covariance was while it was not.
void print_hidden_and_visible(const std::vector<Row>& rows) {
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
}

}  // namespace

CommandHelp evaluate_help() {
  return {"evaluate", kSummary, specs()};
}

int evaluate_command(const std::vector<std::string>& raw) {
  const auto option_specs = specs();
  const Arguments args(raw, option_specs);
  if (args.help()) {
    std::cout << usage(evaluate_help());
    return 0;
  }
  const EvaluateRequest r = evaluate_request(args);
  const LogReadOptions log_options = log_options_from(args, r.in);
  const MeasurementLog log = read_whole_log(r.in, log_options, "evaluate", false);
  if (log.objects.size() > 1 && assumes_top_down_camera(r.settings) &&
      std::find(r.names.begin(), r.names.end(), "opf") != r.names.end())
    std::cerr << missing_camera_warning("evaluate");
  const GroundTruth truth = read_truth(args, r.truth_path, log);
  require_truth_for_every_estimate(log, truth, r.truth_path);

  std::printf("opf evaluate: %s, %zu frames, %zu objects, %zu %s, %zu + %zu particles\n\n",
              r.in.c_str(), log.frames.size(), log.objects.size(), r.seeds,
              r.seeds == 1 ? "seed" : "seeds", r.settings.pf.translation_particles,
              r.settings.pf.rotation_particles);
  RunNotes notes;
  const std::vector<Row> rows = run_every_estimator(r, log, truth, notes);
  print_hidden_and_visible(rows);
  print_calibration(rows, r.alert_distance);
  print_hypotheses(rows);
  if (const auto path = args.get("hidden-profile")) write_hidden_profile(*path, rows);
  if (const auto path = args.get("gap-errors")) write_gap_errors(*path, rows);
  if (const auto path = args.get("out"))
    write_evaluation(*path, rows,
                     provenance_json(command_line("evaluate", raw), {{"", r.settings}}, 2));
  if (notes.unscored > 0)
    std::printf(
        "%zu estimates of frames filled inside gaps of the log had no ground truth and "
        "were not scored\n",
        notes.unscored);
  if (notes.unsized) std::cerr << "opf evaluate: note: " << unsized_log_note() << "\n";
  return 0;
}

}  // namespace opf::cli
