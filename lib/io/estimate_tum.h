#pragma once
// Estimates as TUM trajectories ("timestamp tx ty tz qx qy qz qw", one file per object), the
// format evo (evo_ape, evo_rpe) and most SLAM tools read; the reader is LogFormat::kTum.

#include "opf/core/estimate.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace opf {

/// The comment line a TUM file written here starts with.
void write_tum_header(std::ostream& out);

/// One line: the time, the position and the unit quaternion (x, y, z, w; w >= 0), each number in
/// the shortest text that reads back exactly.
void write_tum_row(std::ostream& out, const Estimate& estimate);

/// Where each object's trajectory goes: `out` itself for one object, else
/// <out's folder>/<out's stem>_<object><out's extension> (a '/' in a name becomes '_').
std::vector<std::filesystem::path> tum_paths(const std::filesystem::path& out,
                                             const std::vector<std::string>& objects);

}  // namespace opf
