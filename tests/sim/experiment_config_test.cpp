#include "opf/sim/experiment_config.h"

#include "opf/io/input_error.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace opf::sim {
namespace {

const std::string kMinimal =
    "name: tiny\n"
    "frames: 10\n"
    "objects_of_interest: ball\n"
    "bodies:\n"
    "  - name: ball\n"
    "    shape: sphere\n"
    "    size: [0.025]\n"
    "    colour: [220, 30, 30]\n"
    "    waypoints: [{t: 0, position: [0.4, 0, 0]}, {t: 1, position: [0.5, 0, 0]}]\n";

TEST(ExperimentConfig, ReadsAMinimalExperimentWithDefaults) {
  const ExperimentConfig c = parse_experiment(kMinimal, "tiny.yaml");
  EXPECT_EQ(c.name, "tiny");
  EXPECT_EQ(c.frames, 10);
  EXPECT_EQ(c.rate, 30.0);
  ASSERT_EQ(c.bodies.size(), 1u);
  EXPECT_EQ(c.bodies[0].body.shape, Shape::kSphere);
  EXPECT_EQ(c.bodies[0].body.size, Eigen::Vector3d(0.025, 0.025, 0.025));
  EXPECT_EQ(c.bodies[0].body.colour.r, 220);
  EXPECT_EQ(c.bodies[0].waypoints.size(), 2u);
  EXPECT_EQ(c.camera.position, Eigen::Vector3d(0.55, 0.0, 0.49));
  EXPECT_EQ(c.objects_of_interest, std::vector<std::string>{"ball"});
  EXPECT_TRUE(c.measurement.state_sizes);
}

TEST(ExperimentConfig, TheBundledGeneralOpFollowsThePaper) {
  const ExperimentConfig c =
      load_experiment(std::string(OPF_SOURCE_DIR) + "/experiments/general_op.yaml");
  EXPECT_EQ(c.frames, 330);
  EXPECT_EQ(c.camera.position, Eigen::Vector3d(0.55, 0.0, 0.49));
  const ScriptedScene scene(c.bodies);
  // Paper geometry: the mugs start at [0.4, +-0.15, 0.03], the tray sits at [0.55, -0.09, 0.2],
  // the left mug ends step 1 at [0.8, 0.15, 0.03] with the ball under it, and the ball ends step 2
  // at [0.3, -0.35, 0].
  EXPECT_LT((scene.pose_of("left_mug", 0.0).position - Eigen::Vector3d(0.4, 0.15, 0.03)).norm(),
            1e-12);
  EXPECT_LT((scene.pose_of("right_mug", 0.0).position - Eigen::Vector3d(0.4, -0.15, 0.03)).norm(),
            1e-12);
  EXPECT_LT((scene.pose_of("tray", 5.0).position - Eigen::Vector3d(0.55, -0.09, 0.2)).norm(),
            1e-12);
  EXPECT_LT((scene.pose_of("ball", 150 / 30.0).position - Eigen::Vector3d(0.8, 0.15, 0.0)).norm(),
            1e-9);
  EXPECT_LT(
      (scene.pose_of("left_mug", 150 / 30.0).position - Eigen::Vector3d(0.8, 0.15, 0.03)).norm(),
      1e-9);
  EXPECT_LT((scene.pose_of("ball", 329 / 30.0).position - Eigen::Vector3d(0.3, -0.35, 0.0)).norm(),
            0.01);
}

TEST(ExperimentConfig, TheBundledBaseballUsesMotionCaptureWithADropout) {
  const ExperimentConfig c =
      load_experiment(std::string(OPF_SOURCE_DIR) + "/experiments/baseball.yaml");
  EXPECT_EQ(c.sensor, SensorKind::kMotionCapture);
  ASSERT_EQ(c.dropouts.size(), 1u);
  EXPECT_EQ(c.dropouts[0].to - c.dropouts[0].from, 0.5);  // paper: capture disabled for 0.5 s
  ASSERT_TRUE(c.bodies[0].flight.has_value());
  EXPECT_EQ(c.rate, 100.0);
  // Its own settings (the order-2 fit) under the paper preset only.
  EXPECT_EQ(c.paper_preset_config.filename(), "baseball_paper.yaml");
}

TEST(ExperimentConfig, EveryBundledExperimentLoads) {
  int count = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(OPF_SOURCE_DIR) + "/experiments")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    const ExperimentConfig c = load_experiment(entry.path());
    const ScriptedScene scene(c.bodies);
    EXPECT_GT(c.frames, 0);
    EXPECT_EQ(c.name, entry.path().stem().string());
    for (const auto& object : c.objects_of_interest) EXPECT_NO_THROW(scene.index_of(object));
    ++count;
  }
  EXPECT_EQ(count, 6);  // general_op, sugar_drop, baseball, cups_game, rolling_ball, twin_mugs
}

InputError error_of(const std::string& yaml) {
  try {
    parse_experiment(yaml, "bad.yaml");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << yaml;
  return InputError("", 0, "", "");
}

TEST(ExperimentConfig, ADetectorMayStateNoSizes) {
  EXPECT_FALSE(parse_experiment(kMinimal + "measurement: {state_sizes: false}\n", "tiny.yaml")
                   .measurement.state_sizes);
  const InputError e = error_of(kMinimal + "measurement:\n  state_sizes: 0.5\n");
  EXPECT_EQ(e.field(), "measurement.state_sizes");
  EXPECT_EQ(e.line(), 11u);
}

TEST(ExperimentConfig, ErrorsNameTheKeyAndLine) {
  std::string bad = kMinimal;
  bad.replace(bad.find("sphere"), 6, "cone");
  InputError e = error_of(bad);
  EXPECT_EQ(e.field(), "bodies[0].shape");
  EXPECT_EQ(e.line(), 6u);

  bad = kMinimal;
  bad.replace(bad.find("objects_of_interest: ball"), 25, "objects_of_interest: mug");
  EXPECT_EQ(error_of(bad).field(), "objects_of_interest");

  bad = kMinimal;
  bad.replace(bad.find("{t: 1,"), 6, "{t: 0,");
  EXPECT_EQ(error_of(bad).field(), "bodies[0].waypoints[1].t");

  bad = kMinimal + "    carried: [{from: 0, to: 1, by: nobody}]\n";
  EXPECT_EQ(error_of(bad).field(), "bodies");

  bad = kMinimal + "dropouts: [{from: 1, to: 2}]\n";
  EXPECT_EQ(error_of(bad).field(), "dropouts");  // only for motion capture

  // 2^32 + 1 frames would wrap to 1 in the int frame counter, 3e9 to a negative count.
  for (const char* frames : {"frames: 4294967297", "frames: 3000000000"}) {
    bad = kMinimal;
    bad.replace(bad.find("frames: 10"), 10, frames);
    e = error_of(bad);
    EXPECT_EQ(e.field(), "frames") << frames;
    EXPECT_NE(std::string(e.what()).find("below 2^31"), std::string::npos) << e.what();
  }

  // A rate near zero made the frame interval overflow (the run ended in an unrelated error);
  // the bounds are the log reader's: frames 10 s to 1 ns apart.
  for (const char* rate : {"rate: 1e-300", "rate: 0.09", "rate: 1.1e9"}) {
    e = error_of(kMinimal + rate + "\n");
    EXPECT_EQ(e.field(), "rate") << rate;
    EXPECT_EQ(e.line(), 10u) << rate;
  }
  EXPECT_EQ(parse_experiment(kMinimal + "rate: 0.1\n", "tiny.yaml").rate, 0.1);
  EXPECT_EQ(parse_experiment(kMinimal + "rate: 1e9\n", "tiny.yaml").rate, 1e9);
  // Noise past kMaxNoise (1e6) turns the detections' and the estimates' squares into inf.
  e = error_of(kMinimal + "measurement: {position_noise: 1e308}\n");
  EXPECT_EQ(e.field(), "measurement.position_noise");
  EXPECT_EQ(error_of(kMinimal + "measurement: {orientation_noise: 2e6}\n").field(),
            "measurement.orientation_noise");
  EXPECT_EQ(parse_experiment(kMinimal + "measurement: {position_noise: 1e6}\n", "tiny.yaml")
                .measurement.position_noise,
            1e6);

  // A camera no look-at can place: named at its key, where the renderer's own error had no line.
  e = error_of(kMinimal + "camera:\n  position: [0, 0, 1]\n  look_at: [0, 0, 1]\n");
  EXPECT_EQ(e.field(), "camera.look_at");
  EXPECT_EQ(e.line(), 12u);
  e = error_of(kMinimal +
               "camera:\n  position: [0, 0, 1]\n  look_at: [0, 0, 0]\n  up: [0, 0, 2]\n");
  EXPECT_EQ(e.field(), "camera.up");
  EXPECT_EQ(e.line(), 13u);

  // The camera finds a tracked body by its hue: a black one could never be measured.
  bad = kMinimal;
  bad.replace(bad.find("[220, 30, 30]"), 13, "[0, 0, 0]");
  e = error_of(bad);
  EXPECT_EQ(e.field(), "bodies[0].colour");
  EXPECT_EQ(e.line(), 8u);
  bad = kMinimal;
  bad.replace(bad.find("[0.5, 0, 0]"), 11, "[1e300, 0, 0]");
  EXPECT_EQ(error_of(bad).field(), "bodies[0].waypoints[1].position");
  EXPECT_EQ(error_of(kMinimal + "measurement: {min_area_pixels: 307201}\n").field(),
            "measurement.min_area_pixels");

  // Another body of the ball's hue would be taken for it by the camera (a red mug: the ball's
  // estimate followed the mug, 0.23 m off, and was never hidden).
  const std::string red_cup =
      "  - name: cup\n    shape: sphere\n    size: [0.03]\n    colour: [255, 20, 0]\n"
      "    waypoints: [{t: 0, position: [0.2, 0, 0]}]\n";
  e = error_of(kMinimal + red_cup);
  EXPECT_EQ(e.field(), "bodies[1].colour");
  EXPECT_EQ(e.line(), 13u);
  EXPECT_NE(std::string(e.what()).find("tracked body 'ball'"), std::string::npos) << e.what();
  e = error_of(kMinimal + red_cup + "    tracked: false\n");
  EXPECT_EQ(e.field(), "bodies[1].colour");  // untracked, still seen as the ball
  std::string grey_cup = red_cup;
  grey_cup.replace(grey_cup.find("[255, 20, 0]"), 12, "[150, 150, 150]");
  EXPECT_NO_THROW(parse_experiment(kMinimal + grey_cup + "    tracked: false\n", "tiny.yaml"));
  // Motion capture identifies markers, not hues: a red cup beside the ball, or a black ball.
  EXPECT_NO_THROW(parse_experiment(kMinimal + red_cup + "sensor: motion_capture\n", "tiny.yaml"));
  bad = kMinimal;
  bad.replace(bad.find("[220, 30, 30]"), 13, "[0, 0, 0]");
  EXPECT_NO_THROW(parse_experiment(bad + "sensor: motion_capture\n", "tiny.yaml"));

  bad = kMinimal + "sensor: lidar\n";
  EXPECT_EQ(error_of(bad).field(), "sensor");

  bad = kMinimal + "camera: {fov: 60}\n";
  e = error_of(bad);
  EXPECT_EQ(e.field(), "camera.fov");
  EXPECT_NE(std::string(e.what()).find("vertical_fov_deg"), std::string::npos) << e.what();

  bad = kMinimal + "paper_preset_config: nowhere.yaml\n";
  e = error_of(bad);
  EXPECT_EQ(e.field(), "paper_preset_config");
  EXPECT_EQ(e.line(), 10u);
  EXPECT_NE(std::string(e.what()).find("no file nowhere.yaml"), std::string::npos) << e.what();
}

// The names name the result files: a name no file can carry (a '/', nothing, 300 characters)
// failed the run at its last write, after every seed had run; now the reader refuses it at its
// line, and a name in the files' alphabet of up to 64 characters is taken.
TEST(ExperimentConfig, NamesAreFileNames) {
  for (const std::string& name : std::vector<std::string>{"a/b", "\"\"", "..", ".hidden", "-x",
                                                          "two words", std::string(65, 'a')}) {
    std::string bad = kMinimal;
    bad.replace(bad.find("name: tiny"), 10, "name: " + name);
    const InputError e = error_of(bad);
    EXPECT_EQ(e.field(), "name") << name;
    EXPECT_EQ(e.line(), 1u) << name;
    EXPECT_NE(std::string(e.what()).find("expected the experiment's name of 1 to 64 letters"),
              std::string::npos)
        << e.what();
    bad = kMinimal;
    bad.replace(bad.find("name: ball"), 10, "name: " + name);
    const InputError body = error_of(bad);
    EXPECT_EQ(body.field(), "bodies[0].name") << name;
    EXPECT_EQ(body.line(), 5u) << name;
  }
  std::string missing = kMinimal;
  missing.erase(0, missing.find('\n') + 1);
  EXPECT_EQ(error_of(missing).field(), "name");
  std::string good = kMinimal;
  const std::string longest = "v1.0-" + std::string(59, 'b');
  good.replace(good.find("name: tiny"), 10, "name: " + longest);
  EXPECT_EQ(parse_experiment(good, "tiny.yaml").name, longest);
}

// The default preset is one set of settings for every experiment: a file that would change it
// for itself is refused, with where its settings can go instead.
// The closed loop's hand moves by -k_p e dt a frame: a gain past the frame rate overshoots
// every frame (1e300 sent the hand, and the frames CSV, to infinity).
TEST(ExperimentConfig, TheControllersGainStopsAtTheFrameRate) {
  std::ifstream file(std::string(OPF_SOURCE_DIR) + "/experiments/sugar_drop.yaml");
  std::stringstream text;
  text << file.rdbuf();
  const std::string shipped = text.str();
  ASSERT_NE(shipped.find("kp_nominal: 3.0"), std::string::npos);
  for (const char* gain : {"kp_nominal: 30.5", "kp_nominal: 1e300"}) {
    std::string bad = shipped;
    bad.replace(bad.find("kp_nominal: 3.0"), 15, gain);
    const InputError e = error_of(bad);
    EXPECT_EQ(e.field(), "closed_loop.controller.kp_nominal") << gain;
    EXPECT_EQ(e.line(), 34u) << gain;
  }
  std::string at_rate = shipped;
  at_rate.replace(at_rate.find("kp_nominal: 3.0"), 15, "kp_nominal: 30");
  EXPECT_EQ(parse_experiment(at_rate, "sugar_drop.yaml").closed_loop->controller.kp_nominal, 30.0);
}

TEST(ExperimentConfig, AnExperimentCannotChangeTheDefaultSettings) {
  const InputError e = error_of(kMinimal + "estimator_config: configs/estimators.yaml\n");
  EXPECT_EQ(e.field(), "estimator_config");
  EXPECT_EQ(e.line(), 10u);
  const std::string message = e.what();
  EXPECT_NE(message.find("--config FILE.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("paper_preset_config"), std::string::npos) << message;
}

}  // namespace
}  // namespace opf::sim
