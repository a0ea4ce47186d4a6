#pragma once
// Synthetic dropouts in a measurement log: the chosen objects' detections are removed in periodic
// windows, so that the unmodified log is the ground truth of the frames they are missing from
// (real motion, known answer). Exact and deterministic: the same log and windows always blank the
// same rows.

#include <cstddef>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace opf {

/// Windows [start + k period, start + k period + length) for k = 0, 1, 2, ..., in seconds.
struct DropoutWindows {
  double start = 1.0;
  double period = 2.0;
  double length = 0.0;
};

/// Times closer than this to a window's edge count as lying on it, so that frame times like
/// k / fps fall where their exact values do (1.3 is not inside [1.0, 1.0 + 0.3)).
inline constexpr double kDropoutTimeTolerance = 1e-9;

/// Throws std::invalid_argument unless start is finite and 0 < length < period (finite).
void check_dropout_windows(const DropoutWindows& windows);

/// Whether `t` lies in one of the windows.
bool in_dropout_window(double t, const DropoutWindows& windows);

struct DropoutCounts {
  std::size_t rows = 0;     ///< data rows copied
  std::size_t blanked = 0;  ///< rows whose pose was removed (rows already without one not counted)
};

/// Copies the measurement log `in` (named `source` in errors) to `out`, emptying the pose fields
/// x,y,z,qx,qy,qz,qw (x,y,z in a log of positions) of every row of `objects` (of every object when
/// empty) whose t lies in a window. The row itself stays, so its frame stays in the log even when
/// the object is the only one there; the object is unobserved at that t either way
/// (measurement_log.h). Everything else, the header, the row order and any further columns, is
/// copied field by field. Throws InputError for a malformed log or an object of `objects` with no
/// row in it, std::invalid_argument for bad windows.
DropoutCounts apply_dropout(std::istream& in, const std::string& source, std::ostream& out,
                            const std::vector<std::string>& objects, const DropoutWindows& windows);

}  // namespace opf
