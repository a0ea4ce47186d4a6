#pragma once
// opf.Tracker: an opf::Tracker stepped from Python. It checks every input before the tracker
// sees it (a refused step leaves the tracker as it was) and takes one step at a time: the GIL is
// released while the estimators run, so another Python thread may call step meanwhile and waits
// for the first step to end.

#include "py_estimate.h"
#include "settings_arguments.h"

#include "opf/core/tracker.h"

#include <pybind11/pybind11.h>

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace opf::python {

class PyTracker {
 public:
  PyTracker(const std::string& estimator, std::uint64_t seed, const SettingsArguments& settings);

  /// detections: {object: [x, y, z, qx, qy, qz, qw] or None}. Throws std::invalid_argument
  /// (ValueError) naming the object and the field of a bad input, or when t does not follow the
  /// previous step's.
  std::map<std::string, PyEstimate> step(double t,
                                         const std::map<std::string, pybind11::object>& detections);

  std::vector<PyEstimate> hypotheses();

 private:
  PyTracker(const std::string& estimator, std::uint64_t seed, const EstimatorSettings& settings);

  std::mutex mutex_;     // held by the step under way (and readers), taken without the GIL
  double epsilon_safe_;  // the feedback module's alert threshold
  Tracker tracker_;
};

}  // namespace opf::python
