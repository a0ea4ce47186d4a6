#pragma once
// The estimator output file: one CSV row per object per frame, byte-deterministic, and a reader for
// it (tests and evaluation).
//
// Columns: t,object,x,y,z,qx,qy,qz,qw,trace,mode,std_x,std_y,std_z,std_yaw,std_pitch,std_roll,
// hypothesis,alert,occlusion_probability,model
// Numbers are the shortest text that reads back exactly; the quaternion has qw >= 0; trace is the
// observation-covariance trace used at the step; mode says what produced the estimate (see
// EstimateMode), then what the step had to do to stay usable ("measured+reset", see
// RecoveryEvents); std_* are the square roots of the covariance diagonal over MRPT's (x, y, z, yaw,
// pitch, roll); hypothesis is 0 for the object's main estimate and 1, 2, ... for further
// hypotheses (extra rows); alert is 1 when trace >= epsilon_safe; occlusion_probability is empty
// unless the estimator models it; model names the motion models the dynamics module extrapolates
// with (per axis x, y, z, then rotation: cp, cv, ca or ballistic; co or cw), empty otherwise.

#include "opf/core/estimate.h"

#include <mrpt/poses/CPose3D.h>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace opf {

void write_estimate_header(std::ostream& out);
void write_estimate_row(std::ostream& out, const Estimate& estimate);

/// One row of an estimate file. The standard deviations are not read back.
struct EstimateRecord {
  double t = 0.0;
  std::string object;
  mrpt::poses::CPose3D pose;
  double trace = 0.0;
  std::string mode;
  int hypothesis = 0;  ///< 0 when the file has no hypothesis column
  bool alert = false;  ///< false when the file has no alert column
  std::string model;   ///< empty when the file has no model column
};

/// Reads an estimate file in row order. Throws InputError naming file, line and column.
std::vector<EstimateRecord> read_estimate_csv(const std::filesystem::path& path);

}  // namespace opf
