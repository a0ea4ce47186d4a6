#include "track_log.h"

#include "py_estimate.h"

#include "opf/core/tracker.h"
#include "opf/estimators/registry.h"
#include "opf/io/log_row_reader.h"
#include "opf/io/measurement_log.h"
#include "opf/io/unsized_log_note.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <vector>

namespace py = pybind11;

namespace opf::python {
namespace {

constexpr std::array<const char*, 8> kPoseColumns = {"x",  "y",  "z",  "qx",
                                                     "qy", "qz", "qw", "trace"};
constexpr std::array<const char*, 6> kAxes = {"x", "y", "z", "yaw", "pitch", "roll"};
constexpr std::size_t kCovarianceColumns = 21;  // the upper triangle of the 6x6

py::array_t<double> numbers(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

// The estimate file's columns as they fill, in its order (io/estimate_csv.cpp).
class ColumnTable {
 public:
  ColumnTable(double epsilon_safe, bool covariance)
      : epsilon_safe_(epsilon_safe), covariance_(covariance) {}

  void add(const Estimate& estimate) {
    const PyEstimate p = to_python(estimate, epsilon_safe_);
    t_.push_back(p.t);
    object_.push_back(p.object);
    const std::array<double, 8> pose = {p.position.x(),  p.position.y(),  p.position.z(),
                                        p.quaternion(0), p.quaternion(1), p.quaternion(2),
                                        p.quaternion(3), p.trace};
    for (std::size_t i = 0; i < pose.size(); ++i) pose_[i].push_back(pose[i]);
    mode_.push_back(p.mode);
    for (int i = 0; i < 6; ++i) std_[i].push_back(std::sqrt(p.covariance(i, i)));
    hypothesis_.push_back(p.hypothesis);
    probability_.push_back(p.probability);
    alert_.push_back(p.alert);
    model_.push_back(p.model);
    if (!covariance_) return;
    std::size_t k = 0;
    for (int i = 0; i < 6; ++i)
      for (int j = i; j < 6; ++j) cov_[k++].push_back(p.covariance(i, j));
  }

  py::dict to_dict() const {
    py::dict columns;
    columns["t"] = numbers(t_);
    columns["object"] = py::cast(object_);
    for (std::size_t i = 0; i < pose_.size(); ++i) columns[kPoseColumns[i]] = numbers(pose_[i]);
    columns["mode"] = py::cast(mode_);
    for (std::size_t i = 0; i < std_.size(); ++i)
      columns[py::str(std::string("std_") + kAxes[i])] = numbers(std_[i]);
    columns["hypothesis"] = py::array(py::cast(hypothesis_));
    columns["probability"] = numbers(probability_);
    columns["alert"] = py::array(py::cast(alert_));
    columns["model"] = py::cast(model_);
    if (!covariance_) return columns;
    std::size_t k = 0;
    for (std::size_t i = 0; i < kAxes.size(); ++i)
      for (std::size_t j = i; j < kAxes.size(); ++j)
        columns[py::str(std::string("cov_") + kAxes[i] + "_" + kAxes[j])] = numbers(cov_[k++]);
    return columns;
  }

 private:
  double epsilon_safe_;
  bool covariance_;
  std::vector<double> t_;
  std::vector<std::string> object_;
  std::array<std::vector<double>, 8> pose_;  // kPoseColumns
  std::vector<std::string> mode_;
  std::array<std::vector<double>, 6> std_;
  std::vector<int> hypothesis_;
  std::vector<double> probability_;
  std::vector<bool> alert_;
  std::vector<std::string> model_;
  std::array<std::vector<double>, kCovarianceColumns> cov_;
};

}  // namespace

py::dict track_log(const TrackLogArguments& arguments) {
  // The options are checked in opf track's order, before the log is read.
  const EstimatorSettings settings = settings_from(arguments.settings);
  require_camera_for_line_of_sight(settings);
  const LogReadOptions options = log_options_from(arguments.log, arguments.path);
  ColumnTable table(settings.opf.feedback.epsilon_safe, arguments.covariance);
  UnsizedLogWatch unsized;
  bool positions_only = false;
  {
    const py::gil_scoped_release release;
    Tracker tracker(make_estimator_factory(arguments.estimator, settings), arguments.seed);
    const MeasurementLog log = read_measurement_log(arguments.path, options);
    positions_only = !log.states_orientation;
    // The rows opf track writes: each object's, then the further hypotheses.
    std::vector<Estimate> rows;
    for (const Frame& frame : log.frames) {
      for (const Detection& detection : frame.detections) unsized.saw(detection);
      step_into_rows(tracker, frame, rows);
      for (const Estimate& row : rows) {
        unsized.saw(row);
        table.add(row);
      }
    }
  }
  // opf track's notes, as warnings at the caller of opf.track_log (stack level 2: past the
  // module's own wrapper); the warnings module silences them or makes them errors.
  const auto warn = [](const std::string& note) {
    if (PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 2) != 0) throw py::error_already_set();
  };
  if (positions_only) warn(arguments.path + ": " + positions_only_note());
  if (unsized.note_due()) warn(unsized_log_note());
  return table.to_dict();
}

}  // namespace opf::python
