#pragma once
// A row of the KITTI tracking benchmark's labels (label_02/0000.txt), or of a 3-D tracker's
// results in their format, as one detection (LogFormat::kKitti). The label places a box's bottom
// centre at (x, y, z) in the camera's frame (x right, y down, z forward) and turns it by
// rotation_y about y; its extents along its own axes are (length, height, width), the height
// upwards from the bottom (Geiger et al., "Vision meets Robotics: The KITTI Dataset", IJRR 2013).

#include "opf/io/csv.h"
#include "opf/io/log_row_reader.h"

namespace opf {

/// The current row of `reader` (fields kKittiColumns) into `row`: frame k at t = k *
/// frame_period, the track id the object, the pose of the box's centre (y less half its height),
/// its extents (length, height, width) as row.box. False for a row of track id -1 (DontCare: a
/// region, not an object), which `row` does not take. InputError naming the field for a frame or
/// track id that is not a whole number >= 0, or an extent that is not positive.
bool read_kitti_tracking_row(const csv::Reader& reader, double frame_period, LogRow& row);

}  // namespace opf
