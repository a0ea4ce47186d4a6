// End-to-end tests of the `opf` program: runs the built binary on the bundled example log.

#include "cli/opf_program.h"
#include "opf/io/estimate_csv.h"
#include "opf/io/measurement_log.h"

#include "opf/core/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace opf {
namespace {

namespace fs = std::filesystem;

const std::string kData = std::string(OPF_SOURCE_DIR) + "/experiments/data/";

TEST_F(OpfProgram, TrackRoundTripsTheExampleLog) {
  const fs::path est = dir_ / "est.csv";
  // The default estimator is the OPF.
  ASSERT_EQ(run("track --in " + kData + "example_log.csv --out " + est.string() +
                " --particles 2000 --seed 3"),
            0)
      << err();
  const MeasurementLog log = read_measurement_log(kData + "example_log.csv");
  const MeasurementLog truth = read_measurement_log(kData + "example_truth.csv");
  // The main estimates: one row per object per frame from its first detection on, t copied from
  // the input. Further hypotheses (hypothesis >= 1: the mug, hidden behind the ball, left where
  // it was or carried by the ball) only for an object missing from that frame.
  std::map<std::pair<double, std::string>, bool> detected;
  for (const Frame& frame : log.frames)
    for (const Detection& d : frame.detections) detected[{frame.t, d.object}] = true;
  std::vector<EstimateRecord> rows;
  for (EstimateRecord& r : read_estimate_csv(est)) {
    if (r.hypothesis == 0) {
      rows.push_back(std::move(r));
      continue;
    }
    EXPECT_FALSE(detected.count({r.t, r.object})) << r.object << " t=" << r.t;
  }
  std::size_t expected_rows = 0;
  std::map<std::string, bool> seen;
  for (const Frame& frame : log.frames) {
    for (const Detection& d : frame.detections) seen[d.object] = true;
    expected_rows += seen.size();
  }
  ASSERT_EQ(rows.size(), expected_rows);

  std::map<std::pair<double, std::string>, mrpt::poses::CPose3D> truth_at;
  for (const Frame& f : truth.frames)
    for (const Detection& d : f.detections) truth_at[{f.t, d.object}] = d.pose;
  std::size_t row = 0, hidden_ball = 0;
  double measured_error = 0.0, hidden_ball_error = 0.0;
  std::size_t measured = 0;
  for (const Frame& frame : log.frames) {
    for (std::size_t k = 0; k < seen.size() && row < rows.size() && rows[row].t == frame.t; ++k) {
      const auto& r = rows[row++];
      const bool observed = frame.find(r.object) != nullptr;
      EXPECT_EQ(r.hypothesis, 0);
      const double error = translation_error(r.pose, truth_at.at({r.t, r.object}));
      if (observed) {
        EXPECT_EQ(r.mode, "measured") << r.object << " t=" << r.t;
        measured_error += error;
        ++measured;
      } else if (r.object == "ball") {
        // The ball was rolling when it vanished: the dynamics module extrapolates it.
        EXPECT_EQ(r.mode, "dynamics") << " t=" << r.t;
        hidden_ball_error += error;
        ++hidden_ball;
      }
    }
  }
  EXPECT_EQ(row, rows.size()) << "rows out of frame order";
  EXPECT_EQ(hidden_ball, 30u);  // the ball's one-second occlusion
  // Measurement noise is 5 mm per axis (E||n|| = 8 mm): the filtered estimate must beat it.
  EXPECT_LT(measured_error / static_cast<double>(measured), 0.008);
  // Through the occlusion the fitted line (50 estimates, ~3 mm jitter and ~2 mm random-walk lag
  // at 8 cm/s) keeps the ball within a few mm; standing still would average 4 cm.
  EXPECT_LT(hidden_ball_error / static_cast<double>(hidden_ball), 0.01);
}

// The alert column is the feedback module's rule on each row's trace, for every estimator: the
// baselines' constant trace(Q) = 3 * 0.01^2 + 3 * 0.05^2 = 0.0078 raises none at the default
// epsilon_safe (0.1) and one on every row at 0.0077; the OPF's rows follow their own trace.
TEST_F(OpfProgram, TrackRaisesTheAlertOfEveryEstimatorWhoseTraceReachesEpsilonSafe) {
  std::ofstream(dir_ / "low.yaml") << "opf:\n  feedback:\n    epsilon_safe: 0.0077\n";
  const std::string low = " --config " + (dir_ / "low.yaml").string();
  const fs::path est = dir_ / "est.csv";
  for (const std::string_view estimator : {"pf", "cvkf", "opf"})
    for (const std::string& config : {std::string(), low}) {
      ASSERT_EQ(run("track --quiet --particles 500 --in " + kData + "example_log.csv --out " +
                    est.string() + " --estimator " + std::string(estimator) + config),
                0)
          << err();
      const double epsilon_safe = config.empty() ? 0.1 : 0.0077;
      std::size_t alerts = 0;
      const std::vector<EstimateRecord> rows = read_estimate_csv(est);
      for (const EstimateRecord& r : rows) {
        ASSERT_EQ(r.alert, r.trace >= epsilon_safe) << estimator << config << " t=" << r.t;
        alerts += r.alert;
      }
      if (estimator != "opf") {
        EXPECT_EQ(alerts, config.empty() ? 0 : rows.size()) << estimator;
      }
    }
}

// Every noise setting at its limit (kMaxNoise, 1e6) at once, and the log's stated extra noise at
// the same limit on every fifth row: every estimator still writes finite estimates. Past the
// limit, the settings reader refuses the key (EstimatorSettingsYaml.OutOfRangeValuesAreRejected)
// and the log reader the field; an estimate that is not finite all the same is refused by the
// tracker (Tracker.RefusesAnEstimateThatIsNotFinite).
TEST_F(OpfProgram, TrackStaysFiniteWithEveryNoiseAtItsLimit) {
  std::ofstream(dir_ / "limit.yaml")
      << "pf:\n  process_noise: {translation: 1e6, rotation: 1e6}\n"
         "  observation_noise: {translation: 1e6, rotation: 1e6}\n"
         "cvkf:\n  acceleration_noise: 1e6\n  angular_acceleration_noise: 1e6\n"
         "  observation_noise: {translation: 1e6, rotation: 1e6}\n"
         "  initial_velocity_std: 1e6\n  initial_angular_velocity_std: 1e6\n"
         "imm:\n  process_noise: {position: 1e6, acceleration: 1e6, jerk: 1e6, "
         "angular_acceleration: 1e6}\n"
         "  observation_noise: {translation: 1e6, rotation: 1e6}\n"
         "  initial_velocity_std: 1e6\n  initial_acceleration_std: 1e6\n"
         "  initial_angular_velocity_std: 1e6\n"
         "oapf:\n  spread_growth: 1e3\n";
  std::ifstream example(kData + "example_log.csv");
  std::ofstream noisy(dir_ / "noisy.csv");
  std::string line;
  for (std::size_t i = 0; std::getline(example, line); ++i)
    noisy << line << (i == 0 ? ",extra_noise" : i % 5 == 0 ? ",1000000" : ",") << '\n';
  noisy.close();
  const fs::path est = dir_ / "est.csv";
  for (const std::string_view estimator : {"opf", "pf", "cvkf", "imm", "oapf"})
    for (const fs::path& log : {fs::path(kData + "example_log.csv"), dir_ / "noisy.csv"}) {
      ASSERT_EQ(run("track --quiet --particles 300 --config " + (dir_ / "limit.yaml").string() +
                    " --in " + log.string() + " --out " + est.string() + " --estimator " +
                    std::string(estimator)),
                0)
          << estimator << ' ' << log << ": " << err();
      const std::vector<EstimateRecord> rows = read_estimate_csv(est);
      ASSERT_GT(rows.size(), 300u) << estimator;
      for (const EstimateRecord& r : rows) {
        ASSERT_TRUE(std::isfinite(r.trace) && std::isfinite(r.pose.x()) &&
                    std::isfinite(r.pose.y()) && std::isfinite(r.pose.z()))
            << estimator << ' ' << log << " t=" << r.t;
      }
    }
}

// A box at rest whose detection at frame 15 is 3 m off (a wrong detection). Every particle
// estimator re-scatters at frame 15 and again at 16, when the box is back, and says so in the
// mode column; the Kalman filter has no particles to rescue. With sensor resetting off the
// particle filters' weights underflow at frame 15 instead (3 m is 300 sigmas): the cloud stays
// where it was, so frame 16 is an ordinary update.
TEST_F(OpfProgram, TrackReportsRescuedFramesInTheModeColumn) {
  std::ofstream log(dir_ / "log.csv");
  log << "t,object,x,y,z,qx,qy,qz,qw\n";
  for (int k = 0; k < 30; ++k)
    log << k / 30.0 << ",box," << (k == 15 ? 3.5 : 0.5) << ",0,0,0,0,0,1\n";
  log.close();
  std::ofstream(dir_ / "no_gate.yaml") << "pf:\n  reset_gate: 0\n";
  const auto modes = [&](const std::string& options) {
    const fs::path est = dir_ / "est.csv";
    EXPECT_EQ(run("track --in " + (dir_ / "log.csv").string() + " --out " + est.string() +
                  " --particles 500 " + options),
              0)
        << err();
    std::vector<std::string> column;
    for (const auto& r : read_estimate_csv(est)) column.push_back(r.mode);
    return column;
  };
  const auto expected = [](const std::string& at_15, const std::string& at_16) {
    std::vector<std::string> column(30, "measured");
    column[15] = at_15;
    column[16] = at_16;
    return column;
  };
  for (const char* estimator : {"opf", "pf", "oapf"})
    EXPECT_EQ(modes(std::string("--estimator ") + estimator),
              expected("measured+reset", "measured+reset"))
        << estimator;
  for (const char* estimator : {"cvkf", "imm"})
    EXPECT_EQ(modes(std::string("--estimator ") + estimator), expected("measured", "measured"))
        << estimator;
  const std::string no_gate = " --config " + (dir_ / "no_gate.yaml").string();
  for (const char* estimator : {"opf", "pf"})
    EXPECT_EQ(modes(std::string("--estimator ") + estimator + no_gate),
              expected("measured+underflow", "measured"))
        << estimator;
}

TEST_F(OpfProgram, SameSeedGivesByteIdenticalOutputDifferentSeedDoesNot) {
  for (const char* estimator : {"opf", "pf", "cvkf", "imm", "oapf"}) {
    const std::string common =
        "track --in " + kData + "example_log.csv --particles 500 --estimator " + estimator;
    ASSERT_EQ(run(common + " --seed 8 --out " + (dir_ / "a.csv").string()), 0) << err();
    ASSERT_EQ(run(common + " --seed 8 --out " + (dir_ / "b.csv").string()), 0) << err();
    ASSERT_EQ(run(common + " --seed 9 --out " + (dir_ / "c.csv").string()), 0) << err();
    EXPECT_EQ(read(dir_ / "a.csv"), read(dir_ / "b.csv")) << estimator;
    // The Kalman filters draw no random numbers.
    if (std::string(estimator) != "cvkf" && std::string(estimator) != "imm") {
      EXPECT_NE(read(dir_ / "a.csv"), read(dir_ / "c.csv"));
    }
  }
}

// --preset paper is experiments/configs/paper.yaml, embedded in the program: the same output as
// passing the file, and not the defaults'.
TEST_F(OpfProgram, ThePaperPresetIsThePaperSettingsFile) {
  const std::string track =
      "track --in " + kData + "example_log.csv --particles 500 --seed 2 --out ";
  ASSERT_EQ(run(track + (dir_ / "preset.csv").string() + " --preset paper"), 0) << err();
  ASSERT_EQ(run(track + (dir_ / "file.csv").string() + " --config " + std::string(OPF_SOURCE_DIR) +
                "/experiments/configs/paper.yaml"),
            0)
      << err();
  ASSERT_EQ(run(track + (dir_ / "default.csv").string() + " --preset default"), 0) << err();
  const std::string preset = read(dir_ / "preset.csv");
  EXPECT_FALSE(preset.empty());
  EXPECT_EQ(preset, read(dir_ / "file.csv"));
  EXPECT_NE(preset, read(dir_ / "default.csv"));
  EXPECT_EQ(run(track + (dir_ / "bad.csv").string() + " --preset literal"), 2);
  EXPECT_NE(err().find("expected default or paper, got \"literal\""), std::string::npos) << err();
  EXPECT_FALSE(fs::exists(dir_ / "bad.csv"));
}

TEST_F(OpfProgram, TrackTakesTheCameraAndWarnsWithoutOne) {
  const std::string track =
      "track --in " + kData + "example_log.csv --particles 500 --seed 2 --out ";
  // Two objects, the OPF, plane auto (the default), no camera: a warning that says what is
  // assumed.
  ASSERT_EQ(run(track + (dir_ / "down.csv").string()), 0) << err();
  EXPECT_NE(err().find("warning: no camera position"), std::string::npos) << err();
  ASSERT_EQ(run(track + (dir_ / "above.csv").string() + " --camera 0.4,0,0.8"), 0) << err();
  EXPECT_EQ(err().find("warning"), std::string::npos) << err();
  // plane line_of_sight asks for the camera: without one it is a usage error, not a silent
  // top-down camera; with --camera it is the same run as auto with that camera.
  const fs::path settings = dir_ / "sight.yaml";
  std::ofstream(settings) << "opf:\n  occluder:\n    plane: line_of_sight\n";
  EXPECT_EQ(run(track + (dir_ / "sight.csv").string() + " --config " + settings.string()), 2);
  EXPECT_NE(err().find("opf.occluder.plane is line_of_sight but no camera position is given"),
            std::string::npos)
      << err();
  EXPECT_FALSE(fs::exists(dir_ / "sight.csv"));
  ASSERT_EQ(run(track + (dir_ / "sight.csv").string() + " --config " + settings.string() +
                " --camera 0.4,0,0.8"),
            0)
      << err();
  EXPECT_EQ(read(dir_ / "sight.csv"), read(dir_ / "above.csv"));
  for (const char* bad : {"1,2", "1,2,x", "1,2,3,4", "1,2,inf", "0,0,0,0", "1,2,3,0,1"}) {
    EXPECT_EQ(run(track + (dir_ / "bad.csv").string() + " --camera " + bad), 2) << bad;
    EXPECT_NE(err().find("expected X,Y,Z in metres (a camera there) or X,Y,Z,0 (a camera "
                         "infinitely far in the direction X,Y,Z: parallel lines of sight), got \"" +
                         std::string(bad) + "\""),
              std::string::npos)
        << err();
  }
  // A camera at infinity (a log of `opf detect`, whose z is the depth): no warning, and the
  // settings say so as four numbers.
  ASSERT_EQ(run(track + (dir_ / "far.csv").string() + " --camera 0,0,-1,0"), 0) << err();
  EXPECT_EQ(err().find("warning"), std::string::npos) << err();
  ASSERT_EQ(run("config --dump --camera 0,0,-1,0"), 0) << err();
  EXPECT_NE(out().find("camera_position: [0, 0, -1, 0]"), std::string::npos) << out();
  ASSERT_EQ(run("config --dump --camera 0.4,0,0.8,1"), 0) << err();
  EXPECT_NE(out().find("camera_position: [0.4, 0, 0.8]"), std::string::npos) << out();
}

// A log that states no sizes, once the occluder module has taken an object (carried or left): a
// note naming the columns that state them, once, in CSV and TUM output; none for another
// estimator, for the same log with a radius column, or under --quiet.
TEST_F(OpfProgram, TrackNotesThatTheOccluderModuleWorkedWithoutSizes) {
  const std::string track = "track --camera 0.4,0,0.8 --particles 500 --seed 2 --in ";
  const std::string example = kData + "example_log.csv";
  const std::string note =
      "opf track: note: the occluder module took a hidden object (carried or left) and no "
      "detection states a size (the radius or box_x,box_y,box_z columns)";
  const auto notes = [&] {
    std::size_t count = 0;
    for (auto at = err().find(note); at != std::string::npos; at = err().find(note, at + 1))
      ++count;
    return count;
  };
  const auto taken = [&](const fs::path& est) {
    std::size_t count = 0;
    for (const EstimateRecord& r : read_estimate_csv(est))
      count += r.mode.starts_with("carried") || r.mode.starts_with("left");
    return count;
  };
  ASSERT_EQ(run(track + example + " --out " + (dir_ / "est.csv").string()), 0) << err();
  EXPECT_GT(taken(dir_ / "est.csv"), 0u);
  EXPECT_EQ(notes(), 1u) << err();
  ASSERT_EQ(run(track + example + " --out " + (dir_ / "est.tum").string()), 0) << err();
  EXPECT_EQ(notes(), 1u) << err();
  ASSERT_EQ(run(track + example + " --out " + (dir_ / "cv.csv").string() + " --estimator cvkf"), 0)
      << err();
  EXPECT_EQ(notes(), 0u) << err();
  ASSERT_EQ(run(track + example + " --out " + (dir_ / "quiet.csv").string() + " --quiet"), 0);
  EXPECT_EQ(err(), "");
  // The same log with each detection's radius stated (12 cm: the mug still hides the ball once).
  const fs::path sized_est = dir_ / "sized_est.csv";
  ASSERT_EQ(run(track + with_radius(example, "0.12").string() + " --out " + sized_est.string()), 0)
      << err();
  EXPECT_GT(taken(sized_est), 0u);
  EXPECT_EQ(err().find("note:"), std::string::npos) << err();
}

// The version and the commit built: "opf 0.1.0 (commit 1a2b3c4d5e6f)", or "unknown" outside git.
TEST_F(OpfProgram, VersionNamesTheVersionAndTheCommit) {
  for (const char* flag : {"--version", "version"}) {
    ASSERT_EQ(run(flag), 0) << err();
    const std::string text = out();
    EXPECT_EQ(text.rfind("opf 0.1.0 (commit ", 0), 0u) << text;
    EXPECT_GT(text.size(), std::string("opf 0.1.0 (commit )\n").size()) << text;
    EXPECT_EQ(text.substr(text.size() - 2), ")\n") << text;
  }
}

TEST_F(OpfProgram, EverySubcommandHasHelp) {
  // Each command's help names its own options: the estimator-running ones take --seed.
  for (const auto& [command, option] :
       {std::pair{"track", "--seed"}, std::pair{"evaluate", "--seed"}, std::pair{"run", "--seed"},
        std::pair{"reproduce", "--seed"}, std::pair{"render", "--frame"},
        std::pair{"sweep", "--jobs"}}) {
    ASSERT_EQ(run(std::string(command) + " --help"), 0);
    EXPECT_NE(out().find("Usage: opf " + std::string(command)), std::string::npos) << out();
    EXPECT_NE(out().find(option), std::string::npos) << command;
  }
  ASSERT_EQ(run("--help"), 0);
  EXPECT_NE(out().find("track"), std::string::npos);
}

TEST_F(OpfProgram, BadCommandLinesFailWithAMessageOnStderr) {
  EXPECT_EQ(run("track --out " + (dir_ / "x.csv").string()), 2);
  EXPECT_NE(err().find("'--in' is required"), std::string::npos) << err();
  EXPECT_EQ(run("track --in a --out b --bogus 1"), 2);
  EXPECT_NE(err().find("unknown option '--bogus'"), std::string::npos) << err();
  EXPECT_EQ(run("frobnicate"), 2);
  EXPECT_EQ(run("track --in " + kData + "example_log.csv --out x --estimator nope"), 2);
  EXPECT_NE(err().find("option '--estimator': unknown estimator 'nope'"), std::string::npos)
      << err();
  for (const char* particles : {"0", "2147483648"}) {
    EXPECT_EQ(run("track --in " + kData + "example_log.csv --out x --particles " + particles), 2);
    EXPECT_NE(err().find("'--particles' must be a positive integer below 2^31"), std::string::npos)
        << err();
  }
  // Frames more than 10 s apart: the log reader would take such times as not in seconds; less
  // than 1 ns apart: finer than any log format's clock.
  const std::string rate =
      "'--rate' expects a frame rate in Hz from 0.1 to 1e9 (frames 10 s to 1 ns apart)";
  for (const char* hz : {"0.05", "2e9"}) {
    EXPECT_EQ(run("track --in " + kData + "example_log.csv --out x --rate " + hz), 2) << hz;
    EXPECT_NE(err().find(rate), std::string::npos) << err();
  }
  for (const char* hz : {"1e-300", "1e12"}) {
    EXPECT_EQ(run("detect --video v.mp4 --objects s.yaml --out x.csv --rate " + std::string(hz)), 2)
        << hz;
    EXPECT_NE(err().find(rate), std::string::npos) << err();
  }
}

TEST_F(OpfProgram, MissingInputFileFailsWithoutWritingOutput) {
  const fs::path est = dir_ / "est.csv";
  EXPECT_EQ(run("track --in " + (dir_ / "missing.csv").string() + " --out " + est.string()), 1);
  EXPECT_NE(err().find("missing.csv"), std::string::npos) << err();
  EXPECT_FALSE(fs::exists(est));
}

TEST_F(OpfProgram, RenderWritesTheFrameAndItsDetections) {
  const fs::path png = dir_ / "frame.png";
  // Frame 130 of general_op: the ball is under the mug, the mugs and the tray are in view.
  ASSERT_EQ(run("render " + std::string(OPF_SOURCE_DIR) +
                "/experiments/general_op.yaml --frame 130 --out " + png.string()),
            0)
      << err();
  EXPECT_TRUE(fs::exists(png));
  EXPECT_GT(fs::file_size(png), 1000u);
  const std::string table = out();
  EXPECT_NE(table.find("ball         no"), std::string::npos) << table;
  EXPECT_NE(table.find("left_mug     yes"), std::string::npos) << table;
  EXPECT_EQ(
      run("render " + std::string(OPF_SOURCE_DIR) + "/experiments/general_op.yaml --frame 999"), 2);
  EXPECT_NE(err().find("--frame must be below"), std::string::npos) << err();
}

// Refusals before any run: another log without --truth (the bundled truth is the bundled log's),
// an unknown estimator anywhere in the list, and a log with no detections.
TEST_F(OpfProgram, EvaluateRefusesMeaninglessRunsBeforeRunning) {
  const std::string log = kData + "example_log.csv";
  const fs::path copy = dir_ / "my_log.csv";
  fs::copy_file(log, copy);
  EXPECT_EQ(run("evaluate --in " + copy.string() + " --seeds 1"), 2);
  EXPECT_NE(err().find("option '--truth' is required with --in " + copy.string()),
            std::string::npos)
      << err();
  EXPECT_EQ(out(), "");
  EXPECT_EQ(run("evaluate --seeds 1 --estimators opf,bogus"), 2);
  EXPECT_NE(err().find("unknown estimator 'bogus' (known: "), std::string::npos) << err();
  EXPECT_EQ(out(), "");  // not even opf ran first
  std::ofstream(dir_ / "header.csv") << "t,object,x,y,z,qx,qy,qz,qw\n";
  EXPECT_NE(run("evaluate --in " + (dir_ / "header.csv").string() + " --truth " +
                (dir_ / "header.csv").string()),
            0);
  EXPECT_NE(err().find((dir_ / "header.csv").string() + ": no detections"), std::string::npos)
      << err();
  EXPECT_NE(
      run("track --in " + (dir_ / "header.csv").string() + " --out " + (dir_ / "est.csv").string()),
      0);
  EXPECT_NE(err().find("no detections"), std::string::npos) << err();
  EXPECT_FALSE(fs::exists(dir_ / "est.csv"));
  // A truth that misses an estimate the runs would write: refused before the first run, saying
  // what the truth has instead (it failed after the first run, naming the object and time only).
  const std::string truth = kData + "example_truth.csv";
  std::ifstream truth_in(truth);
  std::ofstream renamed(dir_ / "renamed_truth.csv"), short_truth(dir_ / "short_truth.csv");
  for (std::string line; std::getline(truth_in, line);) {
    const std::size_t ball = line.find(",ball,");
    renamed << (ball == std::string::npos ? line : std::string(line).replace(ball, 6, ",balls,"))
            << "\n";
    if (line.rfind("t,", 0) == 0 || std::stod(line) < 3.0) short_truth << line << "\n";
  }
  renamed.close();
  short_truth.close();
  EXPECT_EQ(run("evaluate --in " + log + " --truth " + (dir_ / "renamed_truth.csv").string() +
                " --seeds 1 --estimators cvkf"),
            1);
  EXPECT_NE(err().find((dir_ / "renamed_truth.csv").string() +
                       ": no ground truth for object 'ball' at t = 0: the truth has no such object "
                       "(its objects: balls, mug); did you mean 'balls'?"),
            std::string::npos)
      << err();
  EXPECT_EQ(out(), "");
  EXPECT_EQ(run("evaluate --in " + log + " --truth " + (dir_ / "short_truth.csv").string() +
                " --seeds 1 --estimators cvkf"),
            1);
  EXPECT_NE(err().find(": no ground truth for object 'ball' at t = 3 (its rows run from 0 to "
                       "2.96667 s; beyond them a row within "),
            std::string::npos)
      << err();
  EXPECT_EQ(out(), "");
  // The bundled log itself needs no --truth (the quick look of the help text).
  EXPECT_EQ(run("evaluate --in " + log + " --seeds 1 --particles 200 --estimators cvkf"), 0)
      << err();
}

TEST_F(OpfProgram, EvaluatePrintsOneRowPerEstimator) {
  ASSERT_EQ(run("evaluate --seeds 2 --particles 500"), 0) << err();
  const std::string table = out();
  for (const char* name : {"\nopf ", "\npf ", "\ncvkf ", "\noapf "})
    EXPECT_NE(table.find(name), std::string::npos) << table;
  EXPECT_NE(table.find("translation [m]"), std::string::npos);
}

}  // namespace
}  // namespace opf
