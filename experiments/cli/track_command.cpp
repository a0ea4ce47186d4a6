#include "track_command.h"

#include "arguments.h"
#include "core/tracker.h"
#include "estimator_arguments.h"
#include "estimators/registry.h"
#include "io/atomic_file.h"
#include "io/estimate_csv.h"
#include "io/measurement_log.h"

#include <iostream>

namespace opf::cli {
namespace {

std::vector<OptionSpec> specs() {
  std::vector<OptionSpec> s = {
      {"in", "LOG.csv", "measurement log: CSV with columns t,object,x,y,z,qx,qy,qz,qw (required)"},
      {"out", "EST.csv", "estimates: t,object,x,y,z,qx,qy,qz,qw,trace,mode,... (required)"},
      {"estimator", "NAME", "estimator to run: opf (default), pf, cvkf or oapf"},
  };
  for (auto& spec : estimator_option_specs()) s.push_back(std::move(spec));
  return s;
}

constexpr const char* kSummary =
    "Replays a log of pose detections (AprilTag, motion capture, a pose tracker) through one\n"
    "estimator per object and writes one row per object and frame, from the object's first\n"
    "detection on. A frame is a distinct t; an object with no row (or empty pose fields) at a\n"
    "frame's t is unobserved there, and the mode column says what the estimator did instead\n"
    "(predicted, dynamics, occluder, random_walk). The OPF treats every object in the log as a\n"
    "possible occluder of every other. Further hypotheses (two equally likely occluders) follow\n"
    "as extra rows with hypothesis >= 1; alert is 1 when trace(Q~) >= epsilon_safe.\n"
    "The output is written only when the whole run succeeded.";

}  // namespace

int track_command(const std::vector<std::string>& raw) {
  const auto option_specs = specs();
  const Arguments args(raw, option_specs);
  if (args.help()) {
    std::cout << usage("track", kSummary, option_specs);
    return 0;
  }
  const std::string in = args.require("in");
  const std::string out = args.require("out");
  const std::string estimator = args.get("estimator").value_or("opf");
  const EstimatorSettings settings = settings_from(args);
  require_camera_for_line_of_sight(settings);

  const MeasurementLog log = read_measurement_log(in);
  const OccluderOptions& occluder = settings.opf.occluder;
  if (estimator == "opf" && log.objects.size() > 1 && settings.opf.modules.occluder &&
      occluder.plane == OccluderPlane::kAuto && !occluder.camera_position)
    std::cerr << "opf track: warning: no camera position (--camera X,Y,Z, or "
                 "opf.occluder.camera_position): the occluder module takes the line of sight as "
                 "straight down (-z)\n";
  Tracker tracker(make_estimator_factory(estimator, settings), seed_from(args), threads_from(args));
  std::size_t rows = 0;
  write_file_atomically(out, [&](std::ostream& os) {
    write_estimate_header(os);
    for (const Frame& frame : log.frames) {
      for (const Estimate& estimate : tracker.step(frame)) {
        write_estimate_row(os, estimate);
        ++rows;
      }
      // Further hypotheses (the OPF's virtual objects) follow as extra rows, hypothesis >= 1.
      for (const Estimate& hypothesis : tracker.hypotheses()) {
        write_estimate_row(os, hypothesis);
        ++rows;
      }
    }
  });
  std::cout << "opf track: " << estimator << " over " << log.frames.size() << " frames, "
            << log.objects.size() << " objects: " << rows << " estimates written to " << out
            << "\n";
  return 0;
}

}  // namespace opf::cli
