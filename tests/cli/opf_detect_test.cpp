// End-to-end tests of `opf detect`: synthetic image folders and videos, the first second of
// OpenCV's sample clip box.mp4 (package opencv-doc, scripts/packages.txt) with the bundled
// box.yaml, and its tree.avi, whose frames are not evenly spaced.

#include "cli/opf_program.h"
#include "opf/io/measurement_log.h"
#include "vision/damaged_video.h"
#include "vision/synthetic_image.h"

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace opf {
namespace {

namespace fs = std::filesystem;

const std::string kRealVideo = std::string(OPF_SOURCE_DIR) + "/experiments/real_video/";

/// The path of `name` (or `name`.gz) in the files of package opencv-doc; empty when not there.
std::string packaged_file(const std::string& name) {
  FILE* pipe = popen("dpkg -L opencv-doc 2>/dev/null", "r");
  if (pipe == nullptr) return "";
  std::string found;
  char line[4096];
  while (std::fgets(line, sizeof line, pipe) != nullptr) {
    std::string path(line);
    while (!path.empty() && (path.back() == '\n' || path.back() == '\r')) path.pop_back();
    for (const std::string& tail : {"/" + name, "/" + name + ".gz"})
      if (found.empty() && path.size() > tail.size() &&
          path.compare(path.size() - tail.size(), tail.size(), tail) == 0)
        found = path;
  }
  pclose(pipe);
  return found;
}

/// box.mp4 from package opencv-doc, decompressed into `dir` when it is shipped gzipped; empty
/// when the package does not have it (or it cannot be decompressed).
std::string box_mp4(const fs::path& dir) {
  const std::string packaged = packaged_file("box.mp4");
  if (packaged.empty() || !packaged.ends_with(".gz")) return packaged;
  const std::string video = (dir / "box.mp4").string();
  return std::system(("gunzip -c '" + packaged + "' > '" + video + "'").c_str()) == 0 ? video : "";
}

/// Six 320x240 frames: a yellow rectangle 60x30 px at (100 + 10k, 120) turned by 20 degrees,
/// missing from frame 3.
void write_frames(const fs::path& dir) {
  fs::create_directories(dir);
  for (int k = 0; k < 6; ++k) {
    cv::Mat frame = vision::test::plain_frame(vision::test::kBackground, {320, 240});
    if (k != 3)
      vision::test::draw_rectangle(frame, {100.0 + 10 * k, 120.0}, {60, 30}, 20.0,
                                   vision::test::kYellow);
    char name[32];
    std::snprintf(name, sizeof name, "frame_%02d.png", k);
    ASSERT_TRUE(cv::imwrite((dir / name).string(), frame));
  }
}

TEST_F(OpfProgram, DetectFindsTheBoxInTheFirstSecondOfBoxMp4) {
  const std::string video = box_mp4(dir_);
  ASSERT_FALSE(video.empty())
      << "box.mp4 not found in package opencv-doc: apt-get install opencv-doc";
  const fs::path log_path = dir_ / "box.csv";
  ASSERT_EQ(run("detect --video " + video + " --objects " + kRealVideo + "box.yaml --out " +
                log_path.string() + " --frames 30"),
            0)
      << err();
  EXPECT_EQ(err().find("detect: ["), std::string::npos) << "a progress bar off a terminal";
  const MeasurementLog log = read_measurement_log(log_path);
  ASSERT_EQ(log.objects, std::vector<std::string>{"box"});
  ASSERT_GE(log.frames.size(), 28u);  // the box is in view throughout
  // t = frame / fps with the clip's 29.97 fps.
  const double dt = log.frames[1].t - log.frames[0].t;
  EXPECT_EQ(log.frames[0].t, 0.0);
  EXPECT_NEAR(1.0 / dt, 29.97, 0.01);
  for (const Frame& frame : log.frames) {
    const double k = frame.t / dt;
    EXPECT_NEAR(k, std::round(k), 1e-6);
    EXPECT_LT(k, 30.0);
  }
  // Frame 0: the box's centre is at about (451, 127) px (checked on an overlay), its long side
  // tilted by about 0.2 rad; over the first second the hand moves it a few px per frame at most.
  const auto& first = log.frames[0].detections.at(0).pose;
  EXPECT_NEAR(first.x() * 1000.0, 451.0, 15.0);
  EXPECT_NEAR(first.y() * 1000.0, 127.0, 15.0);
  EXPECT_NEAR(first.yaw(), 0.22, 0.1);
  for (std::size_t i = 0; i < log.frames.size(); ++i) {
    const auto& pose = log.frames[i].detections.at(0).pose;
    EXPECT_GT(pose.x(), 0.40);
    EXPECT_LT(pose.x(), 0.50);
    EXPECT_GT(pose.y(), 0.09);
    EXPECT_LT(pose.y(), 0.16);
    EXPECT_NEAR(pose.z(), 1.0, 0.05);  // about the size of the first five frames
    EXPECT_NEAR(pose.pitch(), 0.0, 1e-9);
    EXPECT_NEAR(pose.roll(), 0.0, 1e-9);
    if (i == 0) continue;
    const auto& previous = log.frames[i - 1].detections.at(0).pose;
    EXPECT_LT(std::hypot(pose.x() - previous.x(), pose.y() - previous.y()), 0.008) << i;
    EXPECT_LT(std::abs(pose.yaw() - previous.yaw()), 0.05) << i;
  }
  EXPECT_NE(out().find("box: found in"), std::string::npos) << out();
}

// The real-video benchmark's pipeline on its first five seconds: detect, blank 0.6 s every 2 s,
// evaluate. The box moves by hand up to ~0.1 m/s here, so an estimator that holds it where it
// vanished (the PF) is off by up to 6 cm at the end of a gap; the OPF's dynamics module must do
// better, and its reported spread must cover its hidden errors (90% of them). (Its median error
// / spread is low on two short gaps: the cloud at onset, set by the 1 cm observation noise Q,
// dominates; over the whole clip it is 0.3-0.4, see README.)
TEST_F(OpfProgram, DetectDropoutEvaluatePipelineOnBoxMp4) {
  const std::string video = box_mp4(dir_);
  ASSERT_FALSE(video.empty())
      << "box.mp4 not found in package opencv-doc: apt-get install opencv-doc";
  const std::string full = (dir_ / "box.csv").string();
  const std::string dropped = (dir_ / "box_0.6.csv").string();
  ASSERT_EQ(run("detect --video " + video + " --objects " + kRealVideo + "box.yaml --out " + full +
                " --frames 150"),
            0)
      << err();
  ASSERT_EQ(run("dropout --in " + full + " --out " + dropped + " --length 0.6"), 0) << err();
  ASSERT_EQ(run("evaluate --in " + dropped + " --truth " + full +
                " --estimators opf,pf --seeds 1 --particles 2000"),
            0)
      << err();
  // The second table: estimator, hidden [m], hidden [rad], visible [m], visible [rad],
  // coverage, err/sd.
  std::map<std::string, std::vector<double>> rows;
  std::istringstream lines(out());
  std::string line;
  bool second_table = false;
  while (std::getline(lines, line)) {
    if (line.starts_with("estimator  hidden")) second_table = true;
    if (!second_table || line.starts_with("estimator")) continue;
    std::istringstream fields(line);
    std::string name;
    std::vector<double> values;
    double v = 0.0;
    if (!(fields >> name)) break;
    while (fields >> v) values.push_back(v);
    if (values.size() == 6) rows[name] = values;
  }
  ASSERT_TRUE(rows.count("opf") && rows.count("pf")) << out();
  EXPECT_LT(rows["opf"][0], 0.5 * rows["pf"][0]) << out();
  EXPECT_GE(rows["opf"][4], 0.9) << out();
}

TEST_F(OpfProgram, DetectReadsAFolderOfImagesAtTheGivenRate) {
  write_frames(dir_ / "frames");
  std::ofstream(dir_ / "spec.yaml") << "objects:\n  box:\n    hsv: {low: [20, 100, 100], "
                                       "high: [40, 255, 255]}\n    pose: {reference_frames: 1}\n";
  const fs::path log_path = dir_ / "log.csv";
  ASSERT_EQ(
      run("detect --video " + (dir_ / "frames").string() + " --objects " +
          (dir_ / "spec.yaml").string() + " --out " + log_path.string() + " --rate 20 --first 1"),
      0)
      << err();
  EXPECT_EQ(err(), "");  // no progress bar when stderr is not a terminal
  const std::string text = read(log_path);
  EXPECT_EQ(text.substr(0, text.find('\n')), "t,object,x,y,z,qx,qy,qz,qw");
  // The log's frames are 1, 2, 4, 5; reading it fills frame 3, where the box was not found.
  const MeasurementLog filled = read_measurement_log(log_path);
  ASSERT_EQ(filled.frames.size(), 5u);
  EXPECT_TRUE(filled.frames[2].filled);
  EXPECT_TRUE(filled.frames[2].detections.empty());
  EXPECT_NEAR(filled.frames[2].t, 0.15, 1e-12);
  LogReadOptions log_frames_only;
  log_frames_only.fill_gaps = false;
  const MeasurementLog log = read_measurement_log(log_path, log_frames_only);
  ASSERT_EQ(log.frames.size(), 4u);
  const double expected_t[] = {0.05, 0.1, 0.2, 0.25};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(log.frames[i].t, expected_t[i]);
    const auto& pose = log.frames[i].detections.at(0).pose;
    const double u = 100.0 + 10.0 * (expected_t[i] * 20.0);
    EXPECT_NEAR(pose.x(), u / 1000.0, 0.0005);
    EXPECT_NEAR(pose.y(), 0.120, 0.0005);
    EXPECT_NEAR(pose.z(), 1.0, 0.005);
    EXPECT_NEAR(pose.yaw(), 20.0 * M_PI / 180.0, 0.01);
  }
  EXPECT_NE(out().find("found in 4 of 5 frames"), std::string::npos) << out();
  // One object: nothing hides it, so the line of sight does not matter.
  EXPECT_EQ(out().find("--camera"), std::string::npos) << out();
  // Two: how to track the log with the lines of sight its z has.
  std::ofstream(dir_ / "two.yaml")
      << "objects:\n"
         "  box:\n    hsv: {low: [20, 100, 100], high: [40, 255, 255]}\n"
         "  twin:\n    hsv: {low: [20, 100, 100], high: [40, 255, 255]}\n";
  ASSERT_EQ(
      run("detect --video " + (dir_ / "frames").string() + " --objects " +
          (dir_ / "two.yaml").string() + " --out " + (dir_ / "two.csv").string() + " --rate 20"),
      0)
      << err();
  EXPECT_NE(out().find("track it with --camera 0,0,-1,0: z is the depth"), std::string::npos)
      << out();

  // A folder states no frame rate.
  EXPECT_EQ(run("detect --video " + (dir_ / "frames").string() + " --objects " +
                (dir_ / "spec.yaml").string() + " --out " + log_path.string()),
            2);
  EXPECT_NE(err().find("'--rate' is required"), std::string::npos) << err();
}

/// The t column of a detection log, as written.
std::vector<std::string> times_of(const std::string& log_text) {
  std::istringstream in(log_text);
  std::vector<std::string> times;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) times.push_back(line.substr(0, line.find(',')));
  return times;
}

TEST_F(OpfProgram, DetectTimesUnevenlySpacedFramesByTheirTimestamps) {
  // tree.avi states 15 fps and 444 frames, but holds 68, about 0.43 s apart over its 29.6 s: the
  // recorder dropped frames and the container counts them.
  const std::string video = packaged_file("tree.avi");
  ASSERT_FALSE(video.empty())
      << "tree.avi not found in package opencv-doc: apt-get install opencv-doc";
  std::ofstream(dir_ / "spec.yaml") << "objects:\n  trunk:\n    hsv: {low: [0, 40, 80], high: [25, "
                                       "200, 255]}\n    morphology: {open: 5, close: 15}\n";
  const fs::path log_path = dir_ / "tree.csv";
  const std::string command = "detect --video " + video + " --objects " +
                              (dir_ / "spec.yaml").string() + " --out " + log_path.string();
  ASSERT_EQ(run(command), 0) << err();
  EXPECT_NE(err().find("not evenly spaced at 14.9999 Hz (frame 1 is stamped 0.733337 s, not "
                       "0.066667 s)"),
            std::string::npos)
      << err();
  EXPECT_EQ(err().find("missing from the log"), std::string::npos) << err();  // it ends at 29.6 s
  std::vector<std::string> times = times_of(read(log_path));
  ASSERT_EQ(times.size(), 68u);
  EXPECT_EQ(times[0], "0");
  EXPECT_EQ(times[1], "0.733337");
  EXPECT_EQ(times[2], "1.133339");
  EXPECT_NEAR(std::stod(times.back()), 29.533481, 1e-6);

  // A rate given on the command line is kept, without the warning.
  ASSERT_EQ(run(command + " --rate 15"), 0) << err();
  EXPECT_EQ(err().find("not evenly spaced"), std::string::npos) << err();
  times = times_of(read(log_path));
  ASSERT_EQ(times.size(), 68u);
  EXPECT_NEAR(std::stod(times[1]), 1.0 / 15.0, 1e-12);
}

TEST_F(OpfProgram, DetectWarnsWhereADamagedVideoStops) {
  const fs::path video = dir_ / "damaged.avi";
  vision::test::write_mjpeg_video(video, 40, 10.0);
  vision::test::wipe_frames(video, 10, 16);
  std::ofstream(dir_ / "spec.yaml") << "objects:\n  box:\n    hsv: {low: [20, 100, 100], "
                                       "high: [40, 255, 255]}\n";
  const fs::path log_path = dir_ / "log.csv";
  const std::string command = "detect --video " + video.string() + " --objects " +
                              (dir_ / "spec.yaml").string() + " --out " + log_path.string();
  ASSERT_EQ(run(command), 0) << err();
  EXPECT_NE(err().find(video.string() + ": decoding ended after frame 9, about 30 frames (3 s) "
                                        "before the end the video states: they are missing from "
                                        "the log"),
            std::string::npos)
      << err();
  const std::vector<std::string> times = times_of(read(log_path));
  ASSERT_EQ(times.size(), 10u);  // the box in frames 0-9, each at frame / fps
  EXPECT_EQ(times[9], "0.9");

  // An undamaged video: no warning.
  vision::test::write_mjpeg_video(video, 40, 10.0);
  ASSERT_EQ(run(command), 0) << err();
  EXPECT_EQ(err().find("warning"), std::string::npos) << err();
  EXPECT_EQ(times_of(read(log_path)).size(), 40u);
}

TEST_F(OpfProgram, DetectErrorsNameTheFile) {
  write_frames(dir_ / "frames");
  const std::string spec = kRealVideo + "box.yaml";
  const std::string log_path = (dir_ / "log.csv").string();

  EXPECT_EQ(run("detect --video " + (dir_ / "none.mp4").string() + " --objects " + spec +
                " --out " + log_path),
            1);
  EXPECT_NE(err().find((dir_ / "none.mp4").string()), std::string::npos) << err();

  std::ofstream(dir_ / "text.mp4") << "not a video\n";
  EXPECT_EQ(run("detect --video " + (dir_ / "text.mp4").string() + " --objects " + spec +
                " --out " + log_path),
            1);
  EXPECT_NE(err().find((dir_ / "text.mp4").string() + ": cannot be read as a video"),
            std::string::npos)
      << err();

  std::ofstream(dir_ / "bad.yaml") << "objects:\n  box:\n    hsv: {low: [20, 100, 100], "
                                      "high: [40, 255, 255]}\n    min_area: many\n";
  EXPECT_EQ(run("detect --video " + (dir_ / "frames").string() + " --rate 10 --objects " +
                (dir_ / "bad.yaml").string() + " --out " + log_path),
            1);
  EXPECT_NE(err().find((dir_ / "bad.yaml").string() + ":4: key 'objects.box.min_area'"),
            std::string::npos)
      << err();
  EXPECT_NE(err().find("expected a finite number, got \"many\""), std::string::npos) << err();
  EXPECT_FALSE(fs::exists(log_path));

  EXPECT_EQ(run("detect --video " + (dir_ / "frames").string() + " --objects " + spec), 2);
  EXPECT_NE(err().find("'--out' is required"), std::string::npos) << err();
  EXPECT_EQ(run("detect --video " + (dir_ / "frames").string() + " --objects " + spec + " --out " +
                log_path + " --rate 0"),
            2);
  EXPECT_EQ(run("detect --video " + (dir_ / "frames").string() + " --objects " + spec + " --out " +
                log_path + " --rate 10 --first 6"),
            1);
  EXPECT_NE(err().find("none from the first frame asked for (6)"), std::string::npos) << err();
  EXPECT_EQ(run("detect --help"), 0);
  EXPECT_NE(out().find("Usage: opf detect"), std::string::npos);
}

}  // namespace
}  // namespace opf
