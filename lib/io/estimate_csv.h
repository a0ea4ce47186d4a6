#pragma once
// The estimator output file: one CSV row per object per frame, byte-deterministic (numbers in
// their shortest exact text), and a reader for it (tests and evaluation). Its columns and their
// meaning are documented in one place, docs/formats.md ("The estimate file").

#include "opf/core/estimate.h"

#include <mrpt/poses/CPose3D.h>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace opf {

/// Opt-in columns of the estimate file.
struct EstimateColumns {
  /// The full 6x6 pose covariance over (x, y, z, yaw, pitch, roll), its upper triangle row by row
  /// as 21 columns cov_x_x, cov_x_y, ..., cov_roll_roll (m^2, m rad, rad^2), so calibration can
  /// be checked with other tools.
  bool covariance = false;
};

void write_estimate_header(std::ostream& out, EstimateColumns columns = {});
/// `epsilon_safe`: the feedback module's threshold; the alert column is safety_alert at it, for any
/// estimator's estimate.
void write_estimate_row(std::ostream& out, const Estimate& estimate, double epsilon_safe,
                        EstimateColumns columns = {});

/// One row of an estimate file. The standard deviations are not read back.
struct EstimateRecord {
  double t = 0.0;
  std::string object;
  mrpt::poses::CPose3D pose;
  double trace = 0.0;
  std::string mode;
  int hypothesis = 0;        ///< 0 when the file has no hypothesis column
  double probability = 1.0;  ///< 1 when the file has no probability column
  bool alert = false;        ///< false when the file has no alert column
  std::string model;         ///< empty when the file has no model column
};

/// Reads an estimate file in row order. Throws InputError naming file, line and column.
std::vector<EstimateRecord> read_estimate_csv(const std::filesystem::path& path);

}  // namespace opf
