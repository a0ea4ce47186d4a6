#pragma once
// `opf detect`'s pipeline: every frame of a video through one segmenter per object of a
// segmentation spec, the blobs turned into poses, the poses written as a measurement log.

#include "opf/vision/blob_pose.h"
#include "opf/vision/frame_source.h"
#include "opf/vision/object_segmenter.h"
#include "opf/vision/segmentation_spec.h"

#include <cstddef>
#include <functional>
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

/// The measurement log of `detection`: rows in frame order, within a frame in the spec's object
/// order, t = frame / fps; frames where an object was not found have no row for it. Throws
/// std::invalid_argument for a non-positive fps.
void write_detection_log(std::ostream& out, const VideoDetection& detection, double fps);

}  // namespace opf::vision
