#pragma once
// opf.track_log: a measurement log replayed in C++ into the columns of the estimate file
// `opf track` writes for the same log, options and seed.

#include "settings_arguments.h"
#include "track_log_options.h"

#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>

namespace opf::python {

struct TrackLogArguments {
  std::string path;
  std::string estimator = "opf";
  std::uint64_t seed = 1;
  SettingsArguments settings;
  LogArguments log;
  bool covariance = false;  ///< also the 21 cov_* columns (opf track --covariance)
};

/// {column: values} in the file's column order: numpy arrays, and lists of str for object, mode
/// and model. The log's errors are InputErrors naming file, line and column.
pybind11::dict track_log(const TrackLogArguments& arguments);

}  // namespace opf::python
