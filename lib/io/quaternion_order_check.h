#pragma once
// A log written with its quaternions in w, x, y, z order but read as x, y, z, w shows an object
// turned half a turn about x throughout: the first component near 1 and the last near 0. Such an
// object is worth a warning (it may also truly be upside down, so it is not refused).

#include "opf/io/measurement_log.h"

#include <string>
#include <vector>

namespace opf {

/// The objects whose detections (at least kMinDetectionsForOrderCheck) read as x, y, z, w have
/// mean |x| of at least 0.9 and mean |w| of at most 0.3 (within about 50 degrees of half a turn
/// about x, as an object turned by less than that from the identity and written w first reads),
/// in the order the log lists them.
std::vector<std::string> objects_with_w_first_quaternions(const MeasurementLog& log);

inline constexpr std::size_t kMinDetectionsForOrderCheck = 10;

/// The warning for one such object; for a CSV log, naming the --columns that reads w, x, y, z.
std::string w_first_warning(const std::string& object, LogFormat format);

}  // namespace opf
