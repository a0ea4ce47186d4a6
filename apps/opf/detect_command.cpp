#include "detect_command.h"

#include "arguments.h"
#include "command_help.h"
#include "opf/io/atomic_file.h"
#include "opf/io/log_read_options.h"
#include "opf/vision/detection_overlay.h"
#include "opf/vision/frame_source.h"
#include "opf/vision/segmentation_spec.h"
#include "opf/vision/video_detection.h"
#include "output_paths.h"

#include <opencv2/imgcodecs.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

namespace opf::cli {
namespace {

std::vector<OptionSpec> specs() {
  return {
      {"video", "FILE", "a video file, or a folder of images read in name order (required)"},
      {"objects", "SPEC.yaml", "the objects and how to segment each (required)"},
      {"out", "LOG.csv", "measurement log: t,object,x,y,z,qx,qy,qz,qw (required)"},
      {"rate", "HZ", "frame rate, overriding the video's (required for a folder of images)"},
      {"first", "N", "first frame to segment, counting from 0 (default 0)"},
      {"frames", "N", "segment at most N frames (default: to the end)"},
      {"overlay", "DIR", "also write PNGs of the frames with what was found drawn over them"},
      {"overlay-every", "N", "with --overlay: every Nth frame (default 10)"},
  };
}

constexpr const char* kSummary =
    "Finds each object of SPEC.yaml in every frame of a video (an HSV colour range, a dark or\n"
    "light grey-level threshold, or background subtraction following one mover from a start\n"
    "point) and writes one row per object and frame it was found in: the blob's centroid (u, v)\n"
    "at a nominal scale (x = u * metres_per_pixel, y = v * metres_per_pixel, default 1 px = 1 "
    "mm),\n"
    "the depth from its apparent size (z = reference_depth * sqrt(reference_area / area)) and a\n"
    "rotation about z by the principal axis of its moments, unwrapped so that it never jumps by\n"
    "pi. t = frame / rate, or each frame's timestamp where the video's frames are not evenly\n"
    "spaced at its rate. A frame where an object is not found has no row for it (unobserved).\n"
    "Decoding stops at a damaged frame, with a warning of how much of the video is missing.\n"
    "See lib/vision/segmentation_spec.h for the YAML keys. The log is written only when the whole\n"
    "run succeeded.";

/// "\r[#####.....] 123/456" on a terminal; nothing is drawn otherwise.
class ProgressBar {
 public:
  explicit ProgressBar(std::optional<std::size_t> total)
      : total_(total), enabled_(isatty(STDERR_FILENO) != 0) {}
  void update(std::size_t done) {
    if (!enabled_) return;
    constexpr std::size_t kWidth = 40;
    std::string bar;
    if (total_ && *total_ > 0) {
      const std::size_t filled = std::min(kWidth, done * kWidth / *total_);
      bar.append(1, '[').append(filled, '#').append(kWidth - filled, '.').append("] ");
    }
    std::cerr << "\rdetect: " << bar << done;
    if (total_) std::cerr << '/' << *total_;
    std::cerr << " frames" << std::flush;
  }
  void finish() {
    if (enabled_) std::cerr << "\n";
  }

 private:
  std::optional<std::size_t> total_;
  bool enabled_;
};

std::string range_text(double low, double high) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.0f-%.0f", low, high);
  return buffer;
}

// Frames a video's container may state beyond the ones it holds without anything being wrong.
constexpr std::size_t kCountSlack = 2;

/// What a command line asks detect to do, checked before the video is opened.
struct DetectRequest {
  std::filesystem::path video, spec_path, out;
  std::optional<double> rate;
  std::size_t first = 0;
  std::optional<std::size_t> frames;
  std::optional<std::filesystem::path> overlay_dir;
  std::size_t overlay_every = 10;
};

DetectRequest detect_request(const Arguments& args) {
  DetectRequest r;
  r.video = args.require("video");
  r.spec_path = args.require("objects");
  r.out = args.require("out");
  refuse_output_over_input({"--out", r.out.string()},
                           {{"--video", r.video.string()}, {"--objects", r.spec_path.string()}});
  r.rate = args.get_number("rate");
  // As the log reader's limit: a log at a lower rate would be refused as not in seconds.
  if (r.rate && !is_frame_rate(*r.rate))
    throw UsageError{"option '--rate' expects " + std::string(kFrameRateExpectation)};
  r.first = args.get_count("first").value_or(0);
  if (const auto count = args.get_count("frames")) {
    if (*count == 0) throw UsageError{"option '--frames' expects at least 1"};
    r.frames = *count;
  }
  if (args.has("overlay")) r.overlay_dir = *args.get("overlay");
  r.overlay_every = args.get_count("overlay-every").value_or(10);
  if (r.overlay_every == 0) throw UsageError{"option '--overlay-every' expects at least 1"};
  if (args.has("overlay-every") && !r.overlay_dir)
    throw UsageError{"option '--overlay-every' needs --overlay"};
  if (r.overlay_dir) {
    require_folder({"--overlay", r.overlay_dir->string()});
    // A folder of images read as the video would get the overlays among its frames.
    refuse_output_over_input({"--overlay", r.overlay_dir->string()},
                             {{"--video", r.video.string()}});
  }
  return r;
}

/// Detects the spec's objects in the requested frames, with a progress bar and, every
/// overlay_every frames, the overlay image.
vision::VideoDetection detect_frames(const DetectRequest& r, const vision::SegmentationSpec& spec,
                                     vision::FrameSource& source) {
  std::vector<std::string> names;
  for (const auto& object : spec.objects) names.push_back(object.name);
  std::optional<std::size_t> total;
  if (source.frame_count())
    total = *source.frame_count() > r.first ? *source.frame_count() - r.first : 0;
  if (r.frames) total = total ? std::min(*total, *r.frames) : *r.frames;
  ProgressBar progress(total);
  std::size_t done = 0;
  vision::VideoDetection detection = vision::detect_in_video(
      source, spec, r.first, r.frames, [&](const vision::FrameResult& result) {
        progress.update(++done);
        if (r.overlay_dir && (result.frame - r.first) % r.overlay_every == 0) {
          char name[32];
          std::snprintf(name, sizeof name, "frame_%06zu.png", result.frame);
          const std::filesystem::path file = *r.overlay_dir / name;
          if (!cv::imwrite(file.string(), vision::draw_detection_overlay(result, names)))
            throw std::runtime_error("cannot write " + file.string());
        }
      });
  progress.finish();
  return detection;
}

/// Per object: in how many frames it was found, over which frames and where in the image.
void print_objects_found(const vision::VideoDetection& detection) {
  for (const vision::ObjectTrack& object : detection.objects) {
    std::cout << "  " << object.name << ": found in " << object.sightings.size() << " of "
              << detection.frames << " frames";
    if (!object.sightings.empty()) {
      double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
      for (const auto& s : object.sightings) {
        u0 = std::min(u0, s.centroid_px.x);
        u1 = std::max(u1, s.centroid_px.x);
        v0 = std::min(v0, s.centroid_px.y);
        v1 = std::max(v1, s.centroid_px.y);
      }
      std::cout << ", frames " << object.sightings.front().frame << "-"
                << object.sightings.back().frame << ", centroid u " << range_text(u0, u1)
                << " px, v " << range_text(v0, v1) << " px";
    }
    std::cout << "\n";
    if (object.sightings.empty())
      std::cerr << "opf detect: warning: object '" << object.name << "' was never found\n";
  }
}

}  // namespace

CommandHelp detect_help() {
  return {"detect", kSummary, specs()};
}

int detect_command(const std::vector<std::string>& raw) {
  const auto option_specs = specs();
  const Arguments args(raw, option_specs);
  if (args.help()) {
    std::cout << usage(detect_help());
    return 0;
  }
  const DetectRequest r = detect_request(args);
  const vision::SegmentationSpec spec = vision::load_segmentation_spec(r.spec_path);
  vision::FrameSource source(r.video);
  const std::optional<double> fps = r.rate ? r.rate : source.fps();
  if (!fps)
    throw UsageError{"option '--rate' is required: " + r.video.string() + " states no frame rate"};
  if (r.overlay_dir) std::filesystem::create_directories(*r.overlay_dir);
  const vision::VideoDetection detection = detect_frames(r, spec, source);

  // The frames' own timestamps where the container says they are not evenly spaced at its rate
  // (frames dropped as it was recorded): frame / fps would squeeze the motion in time. A rate
  // given on the command line is the user's word and is kept.
  const std::optional<vision::UnevenFrames> uneven =
      r.rate ? std::nullopt : vision::uneven_frames(detection, *fps);
  write_file_atomically(r.out, [&](std::ostream& os) {
    vision::write_detection_log(os, detection, *fps, uneven.has_value());
  });

  const std::size_t last = detection.first_frame + detection.frames - 1;
  std::cout << "opf detect: " << r.video.string() << ", frames " << detection.first_frame << "-"
            << last << " (" << detection.frames << " frames at " << *fps << " Hz)\n";
  print_objects_found(detection);
  // z grows away from the camera along every line of sight: the occluder module's default view,
  // straight down (-z), would take the nearer of two objects for the one behind.
  if (detection.objects.size() > 1)
    std::cout << "  track it with --camera 0,0,-1,0: z is the depth, every line of sight runs "
                 "along +z\n";
  if (const std::size_t missing =
          vision::frames_missing_at_end(detection, *fps, uneven.has_value());
      missing > kCountSlack)
    std::cerr << "opf detect: warning: " << r.video.string() << ": decoding ended after frame "
              << last << ", about " << missing << " frames (" << static_cast<double>(missing) / *fps
              << " s) before the end the video states: they are missing from the log (a truncated "
                 "or damaged file? re-encoding it may recover them)\n";
  if (uneven)
    std::cerr << "opf detect: warning: " << r.video.string()
              << ": the frames are not evenly spaced at " << *fps << " Hz (frame " << uneven->frame
              << " is stamped " << uneven->timestamp << " s, not " << uneven->at_the_rate
              << " s): each row's t is its frame's timestamp; --rate HZ for t = frame / HZ\n";
  std::cout << "  log written to " << r.out.string() << "\n";
  return 0;
}

}  // namespace opf::cli
