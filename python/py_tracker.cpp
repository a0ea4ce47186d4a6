#include "py_tracker.h"

#include "opf/core/option_schema.h"
#include "opf/core/pose_conversion.h"
#include "opf/estimators/registry.h"
#include "opf/io/csv.h"

#include <pybind11/stl.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace py = pybind11;

namespace opf::python {
namespace {

constexpr std::array<const char*, 7> kPoseFields = {"x", "y", "z", "qx", "qy", "qz", "qw"};
// A position alone (at the identity orientation, as a log of positions reads); the pose; with
// extra_noise; with the radius; with the box's three extents.
constexpr std::size_t kPositionFields = 3;
constexpr std::array<std::size_t, 5> kFieldCounts = {kPositionFields, 7, 8, 9, 12};
// The measurement log's tolerance (io/log_row_reader.cpp), and its wording below.
constexpr double kQuaternionNormTolerance = 0.01;

void require_finite(double value, const std::string& where) {
  if (!std::isfinite(value))
    throw std::invalid_argument(where + ": expected a finite number, got " +
                                csv::format_double(value));
}

std::vector<double> pose_fields(const std::string& object, const py::object& pose) {
  const std::string where = "object '" + object + "'";
  std::vector<double> p;
  try {
    p = py::cast<std::vector<double>>(pose);
  } catch (const py::cast_error&) {
    throw std::invalid_argument(where +
                                ": expected a pose [x, y, z, qx, qy, qz, qw] or None, got " +
                                py::cast<std::string>(py::repr(pose)));
  }
  if (std::find(kFieldCounts.begin(), kFieldCounts.end(), p.size()) == kFieldCounts.end())
    throw std::invalid_argument(where +
                                ": expected 7 pose fields [x, y, z, qx, qy, qz, qw] (3 for a "
                                "position alone, 8 with extra_noise, 9 with radius, 12 with "
                                "box_x, box_y, box_z), got " +
                                std::to_string(p.size()));
  for (std::size_t i = 0; i < p.size() && i < kPoseFields.size(); ++i)
    require_finite(p[i], where + ", field '" + kPoseFields[i] + "'");
  if (p.size() == kPositionFields) p.insert(p.end(), {0.0, 0.0, 0.0, 1.0});
  // An eighth number: the detector's stated extra noise (m), as the log's extra_noise column; a
  // ninth: the object's stated radius (m), as its radius column; the tenth to twelfth: its box's
  // full extents (m), as the box_x, box_y, box_z columns, all three or none.
  const auto require_length = [&](std::size_t i, const char* field, const char* what,
                                  bool positive = false) {
    if (p.size() > i && !(std::isfinite(p[i]) && (positive ? p[i] > 0.0 : p[i] >= 0.0)))
      throw std::invalid_argument(where + ", field '" + field + "': expected " + what +
                                  (positive ? " > 0" : " >= 0") + ", got " +
                                  csv::format_double(p[i]));
  };
  require_length(7, "extra_noise", "a standard deviation");
  // As the log's column: past kMaxNoise the estimates turn into NaN (core/option_schema.h).
  if (p.size() > 7 && p[7] > kMaxNoise)
    throw std::invalid_argument(
        where + ", field 'extra_noise': expected a standard deviation up to " +
        csv::format_double(kMaxNoise) + " m, got " + csv::format_double(p[7]));
  require_length(8, "radius", "a radius");
  require_length(9, "box_x", "an extent", true);
  require_length(10, "box_y", "an extent", true);
  require_length(11, "box_z", "an extent", true);
  return p;
}

// The frame of one step, every input checked: the tracker never sees one it would choke on.
Frame frame_from(double t, const std::map<std::string, py::object>& detections) {
  require_finite(t, "field 't'");
  Frame frame;
  frame.t = t;
  for (const auto& [object, pose] : detections) {
    if (object.empty())
      throw std::invalid_argument("object '': expected an object name, got an empty string");
    if (pose.is_none()) continue;  // unobserved in this frame
    const std::vector<double> p = pose_fields(object, pose);
    const Eigen::Quaterniond q(p[6], p[3], p[4], p[5]);
    if (!(std::abs(q.norm() - 1.0) <= kQuaternionNormTolerance))
      throw std::invalid_argument("object '" + object +
                                  "', fields 'qx,qy,qz,qw': expected a unit quaternion (norm "
                                  "within 0.01 of 1), got norm " +
                                  csv::format_double(q.norm()));
    frame.detections.push_back(
        {object, make_pose(Eigen::Vector3d(p[0], p[1], p[2]), q.normalized()),
         p.size() > 7 ? p[7] : 0.0, p.size() > 8 ? p[8] : 0.0,
         p.size() > 11 ? Eigen::Vector3d(p[9], p[10], p[11]) : Eigen::Vector3d::Zero()});
  }
  return frame;
}

// As `opf track` builds them: line_of_sight without a camera position is refused.
EstimatorSettings checked_settings(const SettingsArguments& arguments) {
  EstimatorSettings settings = settings_from(arguments);
  require_camera_for_line_of_sight(settings);
  return settings;
}

}  // namespace

PyTracker::PyTracker(const std::string& estimator, std::uint64_t seed,
                     const SettingsArguments& arguments)
    : PyTracker(estimator, seed, checked_settings(arguments)) {}

PyTracker::PyTracker(const std::string& estimator, std::uint64_t seed,
                     const EstimatorSettings& settings)
    : epsilon_safe_(settings.opf.feedback.epsilon_safe),
      tracker_(make_estimator_factory(estimator, settings), seed) {}

std::map<std::string, PyEstimate> PyTracker::step(
    double t, const std::map<std::string, py::object>& detections) {
  const Frame frame = frame_from(t, detections);  // reads Python objects: with the GIL
  // The GIL first, then the lock: a thread waiting for the lock never holds the GIL that the
  // thread holding the lock needs to return.
  const py::gil_scoped_release release;
  const std::lock_guard lock(mutex_);
  std::map<std::string, PyEstimate> out;
  for (const Estimate& e : tracker_.step(frame)) out.emplace(e.object, to_python(e, epsilon_safe_));
  return out;
}

std::vector<PyEstimate> PyTracker::hypotheses() {
  const py::gil_scoped_release release;
  const std::lock_guard lock(mutex_);
  std::vector<PyEstimate> out;
  for (const Estimate& e : tracker_.hypotheses()) out.push_back(to_python(e, epsilon_safe_));
  return out;
}

}  // namespace opf::python
