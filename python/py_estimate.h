#pragma once
// An Estimate as Python sees it (opf.Estimate): numpy-friendly members, the quaternion with
// qw >= 0 as in estimate files.

#include "opf/core/estimate.h"

#include <Eigen/Core>

#include <string>

namespace opf::python {

struct PyEstimate {
  std::string object;
  double t = 0.0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector4d quaternion = Eigen::Vector4d(0, 0, 0, 1);  // x, y, z, w
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();
  double trace = 0.0;
  std::string mode;
  int hypothesis = 0;
  double probability = 1.0;
  bool alert = false;
  std::string model;
};

/// The numbers are those write_estimate_row writes (io/estimate_csv.h), before formatting; the
/// alert is safety_alert at the feedback module's `epsilon_safe`.
PyEstimate to_python(const Estimate& estimate, double epsilon_safe);

}  // namespace opf::python
