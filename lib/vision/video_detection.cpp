#include "opf/vision/video_detection.h"

#include "opf/io/input_error.h"
#include "opf/io/measurement_log_writer.h"

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace opf::vision {

VideoDetection detect_in_video(FrameSource& source, const SegmentationSpec& spec, std::size_t first,
                               std::optional<std::size_t> count, const FrameObserver& observer) {
  std::vector<ObjectSegmenter> segmenters;
  segmenters.reserve(spec.objects.size());
  VideoDetection detection;
  for (const ObjectSpec& object : spec.objects) {
    segmenters.emplace_back(object.segmentation);
    detection.objects.push_back({object.name, {}, {}});
  }
  const auto none_left = [&] {
    // Where the container states more frames than were decoded, decoding failed there (a
    // damaged file): say so rather than report a short video.
    const std::string decoded =
        source.missing_at_end() > 0
            ? "decoding failed at frame " + std::to_string(source.next_index()) + " of the " +
                  std::to_string(source.next_index() + source.missing_at_end()) +
                  " the video states (a damaged file?)"
            : "the video has " + std::to_string(source.next_index()) + " frames";
    return InputError(
        source.path().string(), 0, "",
        decoded + ", none from the first frame asked for (" + std::to_string(first) + ") on");
  };
  while (source.next_index() < first)
    if (!source.skip()) throw none_left();
  detection.first_frame = first;
  cv::Mat bgr;
  std::vector<std::optional<Blob>> blobs(segmenters.size());
  while ((!count || detection.frames < *count) && source.read(bgr)) {
    const std::size_t frame = source.next_index() - 1;
    if (const std::optional<double> stamp = source.timestamp())
      detection.timestamps.emplace(frame, *stamp);
    for (std::size_t i = 0; i < segmenters.size(); ++i) {
      try {
        blobs[i] = segmenters[i].segment(bgr, frame);
      } catch (const std::invalid_argument& error) {
        throw std::runtime_error("object '" + spec.objects[i].name + "', frame " +
                                 std::to_string(frame) + ": " + error.what());
      }
      if (blobs[i])
        detection.objects[i].sightings.push_back({frame, blobs[i]->centroid_px, blobs[i]->area_px,
                                                  principal_axis_angle(blobs[i]->moments)});
    }
    ++detection.frames;
    if (observer) observer(FrameResult{frame, bgr, segmenters, blobs});
  }
  if (detection.frames == 0) throw none_left();
  if (!count || detection.frames < *count) detection.missing_at_end = source.missing_at_end();
  for (std::size_t i = 0; i < segmenters.size(); ++i)
    detection.objects[i].poses = blob_poses(detection.objects[i].sightings, spec.objects[i].pose);
  return detection;
}

namespace {

// Every segmented frame has a timestamp, and they increase: the frames' own times. (A video with
// B-frames reports its packets' times, out of order, which say nothing.)
bool increasing_timestamps(const VideoDetection& detection) {
  if (detection.frames == 0 || detection.timestamps.size() != detection.frames) return false;
  double previous = -std::numeric_limits<double>::infinity();
  for (const auto& entry : detection.timestamps) {
    if (!(entry.second > previous)) return false;
    previous = entry.second;
  }
  return true;
}

}  // namespace

std::optional<UnevenFrames> uneven_frames(const VideoDetection& detection, double fps) {
  if (!(fps > 0.0) || !increasing_timestamps(detection)) return std::nullopt;
  // From the first frame's timestamp: a video whose times start late (an edit list, a stream cut
  // from a longer one) is still evenly spaced.
  const auto& [first_frame, first_stamp] = *detection.timestamps.begin();
  for (const auto& [frame, stamp] : detection.timestamps) {
    const double at_the_rate = first_stamp + static_cast<double>(frame - first_frame) / fps;
    if (std::abs(stamp - at_the_rate) > 0.5 / fps) return UnevenFrames{frame, stamp, at_the_rate};
  }
  return std::nullopt;
}

std::size_t frames_missing_at_end(const VideoDetection& detection, double fps,
                                  bool frame_timestamps) {
  if (detection.missing_at_end == 0 || detection.frames == 0 || !(fps > 0.0)) return 0;
  const std::size_t last = detection.first_frame + detection.frames - 1;
  const double stated_end = static_cast<double>(last + 1 + detection.missing_at_end) / fps;
  const auto stamp = detection.timestamps.find(last);
  const double last_time = frame_timestamps && stamp != detection.timestamps.end()
                               ? stamp->second
                               : static_cast<double>(last) / fps;
  const double missing = std::round((stated_end - last_time) * fps) - 1.0;
  return missing > 0.0 ? static_cast<std::size_t>(missing) : 0;
}

void write_detection_log(std::ostream& out, const VideoDetection& detection, double fps,
                         bool frame_timestamps) {
  if (!(fps > 0.0) || !std::isfinite(fps))
    throw std::invalid_argument("detection log: the frame rate must be > 0");
  const auto time_of = [&](std::size_t frame) {
    if (!frame_timestamps) return static_cast<double>(frame) / fps;
    const auto it = detection.timestamps.find(frame);
    if (it == detection.timestamps.end())
      throw std::invalid_argument("detection log: frame " + std::to_string(frame) +
                                  " has no timestamp");
    return it->second;
  };
  // (frame, object index) -> pose, to write frame by frame.
  std::map<std::pair<std::size_t, std::size_t>, const BlobPose*> rows;
  for (std::size_t i = 0; i < detection.objects.size(); ++i)
    for (const BlobPose& pose : detection.objects[i].poses) rows[{pose.frame, i}] = &pose;
  write_measurement_header(out);
  for (const auto& [key, pose] : rows)
    write_measurement_row(out, time_of(key.first), detection.objects[key.second].name,
                          pose->position, pose->orientation);
}

}  // namespace opf::vision
