#include "drivers/sweep_spec.h"
#include "drivers/data_directory.h"
#include "drivers/sweep_runs.h"

#include "opf/io/estimator_settings_yaml.h"
#include "opf/io/input_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

namespace opf::experiments {
namespace {

const std::filesystem::path kFile = std::filesystem::path(OPF_SOURCE_DIR) / "experiments" /
                                    "sweeps" / "test_sweep.yaml";  // anchors relative paths

const std::string kSweep = R"(name: kappa_and_modules
experiments: [general_op, baseball]
estimators: [opf, pf]
seeds: 3
particles: 1000
frames: 90
variants:
  - {name: all_on, settings: {}}
  - name: no_dynamics
    settings: {opf.modules.dynamics: false}
parameters:
  opf.uncertainty.kappa: [1.01, 1.1]
  opf.occluder.plane: [line_of_sight, xy, 3d]
)";

// The InputError message of parsing `text`, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_sweep(text, kFile);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepSpec, ReadsEveryKey) {
  const SweepSpec spec = parse_sweep(kSweep, kFile);
  EXPECT_EQ(spec.name, "kappa_and_modules");
  ASSERT_EQ(spec.experiments.size(), 2u);
  EXPECT_EQ(spec.experiments[1].filename(), "baseball.yaml");
  EXPECT_TRUE(std::filesystem::is_regular_file(spec.experiments[0]));
  EXPECT_EQ(spec.estimators, (std::vector<std::string>{"opf", "pf"}));
  EXPECT_EQ(spec.seeds, 3u);
  EXPECT_EQ(spec.particles, 1000u);
  EXPECT_EQ(spec.frames, 90u);
  ASSERT_EQ(spec.variants.size(), 2u);
  EXPECT_EQ(spec.variants[1].name, "no_dynamics");
  ASSERT_EQ(spec.variants[1].settings.size(), 1u);
  EXPECT_EQ(spec.variants[1].settings[0].key, "opf.modules.dynamics");
  EXPECT_EQ(spec.variants[1].settings[0].value, "false");
  EXPECT_EQ(spec.variants[1].settings[0].line, 10u);
  ASSERT_EQ(spec.parameters.size(), 2u);
  EXPECT_EQ(spec.parameters[1].values, (std::vector<std::string>{"line_of_sight", "xy", "3d"}));
}

TEST(SweepSpec, DefaultsToOneVariantAndTheFileName) {
  const SweepSpec spec = parse_sweep("experiments: general_op\nestimators: opf\n", kFile);
  EXPECT_EQ(spec.name, "test_sweep");
  EXPECT_EQ(spec.seeds, 5u);
  EXPECT_EQ(spec.seed, 1u);
  ASSERT_EQ(spec.variants.size(), 1u);
  EXPECT_EQ(spec.variants[0].name, "default");
  EXPECT_TRUE(spec.variants[0].settings.empty());
  EXPECT_EQ(grid_points(spec).size(), 1u);
}

// The grid is every combination, the last parameter varying fastest; each run gets settings that
// the estimator settings reader turns into exactly those options.
TEST(SweepSpec, GridPointsAreEveryCombinationInFileOrder) {
  const SweepSpec spec = parse_sweep(kSweep, kFile);
  const auto points = grid_points(spec);
  ASSERT_EQ(points.size(), 6u);
  EXPECT_EQ(points[0][0].value, "1.01");
  EXPECT_EQ(points[0][1].value, "line_of_sight");
  EXPECT_EQ(points[1][1].value, "xy");
  EXPECT_EQ(points[3][0].value, "1.1");
  EXPECT_EQ(points[5][1].value, "3d");
  const std::vector<SweepSetting> settings = {{"opf.modules.dynamics", "false", 0},
                                              {"opf.uncertainty.kappa", "1.1", 0},
                                              {"opf.occluder.plane", "xy", 0}};
  const EstimatorSettings parsed =
      parse_estimator_settings(settings_yaml(spec, settings), "generated");
  EXPECT_FALSE(parsed.opf.modules.dynamics);
  EXPECT_TRUE(parsed.opf.modules.occluder);
  EXPECT_DOUBLE_EQ(parsed.opf.uncertainty.kappa, 1.1);
  EXPECT_EQ(parsed.opf.occluder.plane, OccluderPlane::kXY);
}

TEST(SweepSpec, ExpandsIntoOneRunPerCombinationAndSeed) {
  const SweepSpec spec = parse_sweep(kSweep, kFile);
  const std::vector<SweepRun> runs = expand_sweep(spec);
  // 2 experiments x 2 estimators x 2 variants x 6 grid points x 3 seeds
  ASSERT_EQ(runs.size(), 144u);
  std::set<std::filesystem::path> directories;
  for (const SweepRun& run : runs) directories.insert(run.directory);
  EXPECT_EQ(directories.size(), runs.size());
  const SweepRun& run = runs[1];
  EXPECT_EQ(run.experiment, "general_op");
  EXPECT_EQ(run.estimator, "opf");
  EXPECT_EQ(run.variant, "all_on");
  EXPECT_EQ(run.seed_index, 1u);
  EXPECT_EQ(run.directory,
            "general_op/opf/all_on/opf.uncertainty.kappa=1.01,opf.occluder.plane=line_of_sight/"
            "seed_1");
  EXPECT_EQ(run.result_file(), run.directory / "general_op_runs.csv");
  const std::vector<std::string> args = run.arguments("/out");
  const auto value_of = [&](const std::string& option) {
    const auto it = std::find(args.begin(), args.end(), option);
    return it == args.end() || it + 1 == args.end() ? std::string("<absent>") : *(it + 1);
  };
  EXPECT_EQ(args[0], "run");
  EXPECT_EQ(value_of("--estimators"), "opf");
  EXPECT_EQ(value_of("--seeds"), "1");
  EXPECT_EQ(value_of("--first-seed"), "1");
  EXPECT_EQ(value_of("--particles"), "1000");
  EXPECT_EQ(value_of("--frames"), "90");
  EXPECT_EQ(value_of("--threads"), "1");
  EXPECT_EQ(value_of("--out"), "/out/" + run.directory.string());
  EXPECT_EQ(value_of("--config"), "/out/" + (run.directory / "settings.yaml").string());
  EXPECT_NE(std::find(args.begin(), args.end(), "--no-figures"), args.end());
}

// `particles` as a parameter sets each run's --particles, not an estimator option.
TEST(SweepSpec, ParticlesParameterSetsTheRunOption) {
  const SweepSpec spec = parse_sweep(
      "experiments: [general_op]\nestimators: [pf]\nseeds: 1\nparameters:\n"
      "  particles: [100, 5000]\n",
      kFile);
  const std::vector<SweepRun> runs = expand_sweep(spec);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].particles, 100u);
  EXPECT_EQ(runs[1].particles, 5000u);
  EXPECT_EQ(runs[1].directory, "general_op/pf/default/particles=5000/seed_0");
  EXPECT_EQ(runs[1].settings_yaml.find("particles"), std::string::npos);
}

// Every bundled sweep loads (its settings pass the estimator settings reader) and expands into
// the runs its comment promises.
TEST(SweepSpec, BundledSweepsLoadAndExpand) {
  const std::map<std::string, std::size_t> expected_runs = {
      {"module_ablation", 75},   {"kappa", 50},
      {"history_length", 50},    {"epsilon_occ", 75},
      {"trajectory_order", 30},  {"occluder_plane", 30},
      {"occluder_offset", 45},   {"resampler", 40},
      {"particle_counts", 80},   {"smoke", 8},
      {"dynamics_predictor", 80}};
  std::size_t found = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kFile.parent_path())) {
    if (entry.path().extension() != ".yaml") continue;
    const SweepSpec spec = load_sweep(entry.path());
    ASSERT_TRUE(expected_runs.count(spec.name)) << entry.path() << ": a new sweep? add it here";
    EXPECT_EQ(spec.name, entry.path().stem().string());
    EXPECT_EQ(expand_sweep(spec).size(), expected_runs.at(spec.name)) << spec.name;
    ++found;
  }
  EXPECT_EQ(found, expected_runs.size());
}

TEST(SweepSpec, ErrorsNameTheFileLineAndKey) {
  const std::string file = kFile.string();
  // A misspelt option in the grid: the estimator settings reader's suggestion, at the sweep's line.
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [opf]\nparameters:\n"
                     "  opf.uncertainty.kapa: [1.1]\n"),
            file + ":4: key 'opf.uncertainty.kapa': unknown key; did you mean 'kappa'?");
  // A value the option rejects, in a variant.
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [opf]\nvariants:\n"
                     "  - name: bad\n    settings: {pf.resampling.scheme: sorted}\n"),
            file +
                ":5: key 'pf.resampling.scheme': expected multinomial, residual, stratified or "
                "systematic, got \"sorted\"");
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [opf, kalman]\n"),
            file +
                ":2: key 'estimators': unknown estimator 'kalman' (known: opf, pf, cvkf, imm, "
                "oapf)");
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [cvfk]\n"),
            file +
                ":2: key 'estimators': unknown estimator 'cvfk' (known: opf, pf, cvkf, imm, "
                "oapf); did you mean 'cvkf'?");
  EXPECT_EQ(error_of("experiments: [no_such_experiment]\nestimators: [opf]\n"),
            file + ":1: key 'experiments': no experiment file " +
                (opf::experiments::bundled_experiments() / "no_such_experiment.yaml").string() +
                " for 'no_such_experiment' (a bare name is "
                "experiments/<name>.yaml, a path is relative to the sweep file)");
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [opf]\nconfig: missing.yaml\n"),
            file + ":3: key 'config': no estimator settings file " +
                (kFile.parent_path() / "missing.yaml").string());
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [opf]\nseed: 1\nsedes: 3\n"),
            file + ":4: key 'sedes': unknown key; did you mean 'seeds'?");
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [opf]\nseeds: 0\n"),
            file + ":3: key 'seeds': expected a positive integer, got \"0\"");
  EXPECT_EQ(
      error_of("experiments: [general_op]\nestimators: [opf]\nparameters:\n"
               "  opf.uncertainty.kappa: 1.1\n"),
      file + ":4: key 'parameters.opf.uncertainty.kappa': expected a non-empty list of values");
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [opf]\nparameters:\n"
                     "  particles: [100, 0]\n"),
            file + ":4: key 'particles': expected a positive integer below 2^31, got \"0\"");
  // The resampler's marks are 32-bit: a count from 2^31 on could only fail in the run.
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [opf]\nparameters:\n"
                     "  particles: [100, 2147483648]\n"),
            file +
                ":4: key 'particles': expected a positive integer below 2^31, got "
                "\"2147483648\"");
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [opf]\nparticles: 2147483648\n"),
            file +
                ":3: key 'particles': expected a particle count below 2^31, got "
                "\"2147483648\"");
  // Every run of a sweep with more frames than an experiment has would fail (opf run --frames).
  EXPECT_EQ(error_of("experiments: [general_op, baseball]\nestimators: [opf]\nframes: 91\n"),
            file + ":3: key 'frames': expected at most 90 frames: 'baseball' has 90");
  // Runs go to <experiment>/<estimator>/...: a name twice would run (and write) the same twice.
  EXPECT_EQ(error_of("experiments: [general_op, ../general_op.yaml]\n"
                     "estimators: [opf]\n"),
            file +
                ":1: key 'experiments': two experiments named 'general_op': their runs would "
                "share one results folder");
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [opf, pf, opf]\n"),
            file + ":2: key 'estimators': estimator 'opf' appears twice");
  EXPECT_EQ(error_of("experiments: [general_op]\nestimators: [opf]\nvariants:\n"
                     "  - {name: a}\n  - {name: a}\n"),
            file + ":5: key 'variants[1].name': expected a name no other variant has, got \"a\"");
  EXPECT_EQ(error_of("estimators: [opf]\n"),
            file + ":1: key 'experiments': missing: which experiments to run");
}

// Settings are written into each run's settings file by their key paths, and the runs into
// folders named after the sweep, its variants and its values: what cannot be either is refused
// at its line. An empty key used to crash the program; a value YAML cannot read again, or a
// long file name, failed with the library's words and no line.
TEST(SweepSpec, RefusesWhatCannotNameASettingOrAFolder) {
  const std::string file = kFile.string();
  const std::string head = "experiments: [general_op]\nestimators: [opf]\n";
  EXPECT_EQ(error_of(head + "variants:\n  - {name: a, settings: {\"\": 1}}\n"),
            file +
                ":4: key 'variants[0].settings.': expected an option's key path, names joined "
                "by dots (e.g. opf.uncertainty.kappa), got \"\"");
  EXPECT_EQ(error_of(head + "parameters:\n  \"\": [1, 2]\n"),
            file +
                ":4: key 'parameters.': expected an option's key path, names joined by dots "
                "(e.g. opf.uncertainty.kappa), got \"\"");
  for (const char* key : {"opf..kappa", ".opf", "opf.", "."})
    EXPECT_EQ(error_of(head + "parameters:\n  \"" + key + "\": [1]\n"),
              file + ":4: key 'parameters." + key +
                  "': expected an option's key path, names joined by dots (e.g. "
                  "opf.uncertainty.kappa), got \"" +
                  key + "\"")
        << key;
  EXPECT_EQ(error_of(head + "parameters:\n  opf.uncertainty.kappa: [\"[1\"]\n"),
            file +
                ":4: key 'opf.uncertainty.kappa': expected a value YAML reads on its own (a "
                "number, a name, or a list in quotes such as \"[a, b]\"), got \"[1\": end of "
                "sequence flow not found");
  // A list in quotes is read as a list: each model left out in turn.
  EXPECT_EQ(error_of(head + "parameters:\n  opf.dynamics.models: [\"[position, velocity]\", "
                            "\"[damped]\"]\n"),
            "");
  for (const char* name : {".", ".."}) {
    EXPECT_EQ(error_of(head + "name: \"" + name + "\"\n"),
              file +
                  ":3: key 'name': expected a name without slashes, other than . and .., got \"" +
                  name + "\"");
    EXPECT_EQ(error_of(head + "variants:\n  - {name: \"" + name + "\"}\n"),
              file +
                  ":4: key 'variants[0].name': expected a name without slashes, other than . and "
                  ".., got \"" +
                  name + "\"");
  }
  EXPECT_EQ(error_of(head + "parameters:\n  opf.dynamics.models: [\"[position, velocity]\", "
                            "\"[position,\tvelocity]\"]\n"),
            file +
                ":4: key 'parameters.opf.dynamics.models': values \"[position, velocity]\" and "
                "\"[position,\tvelocity]\" name one results folder "
                "('opf.dynamics.models=[position,_velocity]'): '/' and whitespace are written as "
                "'_'");
  const std::string long_name(5000, 'x');
  EXPECT_EQ(error_of("experiments: [" + long_name + "]\nestimators: [opf]\n"),
            file + ":1: key 'experiments': no experiment file " +
                (opf::experiments::bundled_experiments() / (long_name + ".yaml")).string() +
                " for '" + long_name +
                "' (a bare name is experiments/<name>.yaml, a path is relative to the sweep file)");
}

// The runs are expanded and checked in memory: ten values of each of five options, twice, is
// 200 000 runs, refused before any is expanded (a grid of 10^10 would exhaust the memory).
TEST(SweepSpec, RefusesMoreRunsThanItCanHold) {
  const std::string message = kFile.string() +
                              ": more than 100000 runs (experiments x estimators x variants x "
                              "grid points x seeds): split the sweep into several files";
  std::string grid = "experiments: [general_op]\nestimators: [opf]\nseeds: 2\nparameters:\n";
  for (const char* key : {"opf.uncertainty.kappa: [1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8, 1.9, 2]",
                          "opf.occluder.reach: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]",
                          "opf.occluder.epsilon_occ: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]",
                          "opf.feedback.epsilon_safe: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]",
                          "pf.reset_gate: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]"})
    grid += std::string("  ") + key + "\n";
  EXPECT_EQ(error_of(grid), message);
  // Ten grid points of 10 000 seeds are 100 000 runs: the limit itself is taken.
  const std::string ten =
      "experiments: [general_op]\nestimators: [opf]\nparameters:\n"
      "  opf.uncertainty.kappa: [1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8, 1.9, "
      "2]\nseeds: ";
  EXPECT_EQ(error_of(ten + "10000\n"), "");
  EXPECT_EQ(error_of(ten + "10001\n"), message);
}

// Each experiment file is read when the sweep is: one that is not an experiment fails with its
// own file and line, before any run.
TEST(SweepSpec, ReadsEachExperimentFile) {
  const std::string error =
      error_of("experiments: [../configs/estimators.yaml]\nestimators: [opf]\n");
  EXPECT_NE(error.find("estimators.yaml:"), std::string::npos) << error;
  EXPECT_EQ(error.find(kFile.string()), std::string::npos) << error;
}

}  // namespace
}  // namespace opf::experiments
