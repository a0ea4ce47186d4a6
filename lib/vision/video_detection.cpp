#include "opf/vision/video_detection.h"

#include "opf/io/input_error.h"
#include "opf/io/measurement_log_writer.h"

#include <cmath>
#include <map>
#include <stdexcept>
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
    return InputError(source.path().string(), 0, "",
                      "the video has " + std::to_string(source.next_index()) +
                          " frames, none from the first frame asked for (" + std::to_string(first) +
                          ") on");
  };
  while (source.next_index() < first)
    if (!source.skip()) throw none_left();
  detection.first_frame = first;
  cv::Mat bgr;
  std::vector<std::optional<Blob>> blobs(segmenters.size());
  while ((!count || detection.frames < *count) && source.read(bgr)) {
    const std::size_t frame = source.next_index() - 1;
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
  for (std::size_t i = 0; i < segmenters.size(); ++i)
    detection.objects[i].poses = blob_poses(detection.objects[i].sightings, spec.objects[i].pose);
  return detection;
}

void write_detection_log(std::ostream& out, const VideoDetection& detection, double fps) {
  if (!(fps > 0.0) || !std::isfinite(fps))
    throw std::invalid_argument("detection log: the frame rate must be > 0");
  // (frame, object index) -> pose, to write frame by frame.
  std::map<std::pair<std::size_t, std::size_t>, const BlobPose*> rows;
  for (std::size_t i = 0; i < detection.objects.size(); ++i)
    for (const BlobPose& pose : detection.objects[i].poses) rows[{pose.frame, i}] = &pose;
  write_measurement_header(out);
  for (const auto& [key, pose] : rows)
    write_measurement_row(out, static_cast<double>(key.first) / fps,
                          detection.objects[key.second].name, pose->position, pose->orientation);
}

}  // namespace opf::vision
