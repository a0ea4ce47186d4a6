#include "render_command.h"

#include "arguments.h"
#include "command_help.h"
#include "drivers/observe_experiment.h"
#include "opf/sim/camera_sensor.h"
#include "opf/sim/scripted_scene.h"
#include "output_paths.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdio>
#include <iostream>

namespace opf::cli {
namespace {

std::vector<OptionSpec> specs() {
  return {{"frame", "K", "frame to render (default 0); t = K / rate"},
          {"out", "FILE.png", "where the image goes (default: <experiment>_frame<K>.png)"}};
}

constexpr const char* kSummary =
    "Renders one frame of an experiment file with its simulated camera, runs the colour-blob\n"
    "detector on it, and writes the image with every detection drawn in (circle at the measured\n"
    "centre, label with the visible fraction); prints the detections. In closed-loop experiments\n"
    "the robot is drawn where the script starts it, since no estimator drives it here.";

}  // namespace

CommandHelp render_help() {
  return {"render EXPERIMENT.yaml", kSummary, specs()};
}

int render_command(const std::vector<std::string>& raw) {
  const auto option_specs = specs();
  const auto [options, positional] = split_positional(raw, option_specs);
  const Arguments args(options, option_specs);
  if (args.help()) {
    std::cout << usage(render_help());
    return 0;
  }
  if (positional.size() != 1) throw UsageError{"expected one experiment file"};
  const sim::ExperimentConfig config = sim::load_experiment(positional[0]);
  const auto frame = args.get_count("frame").value_or(0);
  if (frame >= static_cast<unsigned long long>(config.frames))
    throw UsageError{"--frame must be below the experiment's " + std::to_string(config.frames) +
                     " frames"};
  const std::string out =
      args.get("out").value_or(config.name + "_frame" + std::to_string(frame) + ".png");
  refuse_output_over_input({"--out", out}, {{"the experiment file", positional[0]}});

  const sim::ScriptedScene scene(config.bodies);
  const sim::SceneSnapshot snapshot = scene.at(static_cast<double>(frame) / config.rate);
  sim::CameraSensor sensor(experiments::camera_of(config), {}, experiments::detection_of(config));
  const sim::CameraFrame seen = sensor.observe(snapshot);
  cv::Mat image = sensor.last_image().bgr.clone();

  std::printf("%s frame %llu (t = %.4f s): %zu tracked bodies\n", config.name.c_str(), frame,
              snapshot.t, seen.sightings.size());
  std::printf("%-12s %-9s %-8s %-30s\n", "body", "detected", "visible", "measured centre [m]");
  for (const sim::Sighting& s : seen.sightings) {
    std::printf("%-12s %-9s %-8.2f", s.object.c_str(), s.detected ? "yes" : "no",
                s.visible_fraction);
    if (s.detected) {
      std::printf(" (%.4f, %.4f, %.4f)%s", s.position.x(), s.position.y(), s.position.z(),
                  s.visible_fraction < config.measurement.min_visible_fraction
                      ? "  below min_visible_fraction: unobserved"
                      : "");
      if (const auto pixel = sensor.camera().project(s.position)) {
        const cv::Point2d p(pixel->x(), pixel->y());
        cv::circle(image, p, 6, cv::Scalar(255, 255, 255), 2, cv::LINE_AA);
        char label[64];
        std::snprintf(label, sizeof label, "%s %.0f%%", s.object.c_str(), 100 * s.visible_fraction);
        cv::putText(image, label, p + cv::Point2d(9, -9), cv::FONT_HERSHEY_SIMPLEX, 0.45,
                    cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
      }
    }
    std::printf("\n");
  }
  if (!cv::imwrite(out, image)) throw std::runtime_error("cannot write " + out);
  std::printf("image written to %s\n", out.c_str());
  return 0;
}

}  // namespace opf::cli
