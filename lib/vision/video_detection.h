#pragma once
// `opf detect`'s pipeline: every frame of a video through one segmenter per object of a
// segmentation spec, the blobs turned into poses, the poses written as a measurement log.

#include "opf/vision/blob_pose.h"
#include "opf/vision/frame_source.h"
#include "opf/vision/object_segmenter.h"
#include "opf/vision/segmentation_spec.h"

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace opf::vision {

struct ObjectTrack {
  std::string name;
  std::vector<BlobSighting> sightings;  ///< increasing frame
  std::vector<BlobPose> poses;          ///< one per sighting
};

struct VideoDetection {
  std::size_t first_frame = 0;       ///< number of the first frame segmented
  std::size_t frames = 0;            ///< frames segmented
  std::vector<ObjectTrack> objects;  ///< in the spec's order
  /// Frames the video's container states beyond the last one decoded (FrameSource::missing_at_end;
  /// see frames_missing_at_end for how many are missing).
  std::size_t missing_at_end = 0;
  /// frame -> the container's timestamp of it, s, for every frame segmented that has one.
  std::map<std::size_t, double> timestamps;
};

/// Where the container's timestamps say the frames are not evenly spaced at the stated rate.
struct UnevenFrames {
  std::size_t frame = 0;     ///< the first frame whose timestamp is off the rate's
  double timestamp = 0.0;    ///< s, the container's
  double at_the_rate = 0.0;  ///< s, the first frame's timestamp + frames since / fps
};

/// What a FrameObserver sees after each frame: the frame, then per object (spec order) its
/// segmenter (masks) and its blob, nullopt when unobserved.
struct FrameResult {
  std::size_t frame = 0;
  const cv::Mat& bgr;
  const std::vector<ObjectSegmenter>& segmenters;
  const std::vector<std::optional<Blob>>& blobs;
};
using FrameObserver = std::function<void(const FrameResult&)>;

/// Skips to frame `first` of `source`, then segments `count` frames (all the rest when nullopt)
/// with one ObjectSegmenter per object of `spec`, and computes the poses of each object's
/// sightings. Throws InputError when the video has fewer than first + 1 frames, and
/// std::runtime_error naming the object when its segmenter rejects a frame.
VideoDetection detect_in_video(FrameSource& source, const SegmentationSpec& spec, std::size_t first,
                               std::optional<std::size_t> count,
                               const FrameObserver& observer = {});

/// The first frame whose timestamp lies more than half a frame from where the rate puts it, from
/// the first segmented frame's timestamp on (a video that dropped frames as it was recorded, an
/// AVI with empty chunks for them), when every segmented frame has a timestamp and they increase;
/// nullopt otherwise. Timestamps that do not increase (the packet order of a video with B-frames)
/// say nothing about the spacing.
std::optional<UnevenFrames> uneven_frames(const VideoDetection& detection, double fps);

/// How many of the frames the video states lie after the last one decoded, counted in time: its
/// stated length (frames / fps) past the last frame's time (its timestamp with
/// `frame_timestamps`, as the log has it; frame / fps otherwise or where it has none), less that
/// frame's own period. A
/// video that dropped frames as it was recorded can count them in its length without holding
/// them: its last frame still ends it, and nothing is missing.
std::size_t frames_missing_at_end(const VideoDetection& detection, double fps,
                                  bool frame_timestamps);

/// The measurement log of `detection`: rows in frame order, within a frame in the spec's object
/// order, t = frame / fps, or each frame's own timestamp with `frame_timestamps` (which every
/// frame must have: see uneven_frames); frames where an object was not found have no row for it.
/// Throws std::invalid_argument for a non-positive fps or a missing timestamp.
void write_detection_log(std::ostream& out, const VideoDetection& detection, double fps,
                         bool frame_timestamps = false);

}  // namespace opf::vision
