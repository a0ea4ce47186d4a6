// The Python module `opf` (its compiled part, opf._opf): the Tracker stepped from Python, and a
// whole measurement log replayed in C++ into column arrays. Errors keep their C++ messages
// (InputError and std::invalid_argument as ValueError, other failures as RuntimeError); the GIL
// is released while the estimators run.
#include "opf/core/pose_conversion.h"
#include "opf/core/recovery_events.h"
#include "opf/io/input_error.h"
#include "opf/opf.h"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace {

using Pose7 = std::array<double, 7>;  // x, y, z, qx, qy, qz, qw

// An Estimate as Python sees it: numpy-friendly members, the quaternion with qw >= 0 as in
// estimate files.
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

PyEstimate to_python(const opf::Estimate& e) {
  PyEstimate p;
  p.object = e.object;
  p.t = e.t;
  p.position = opf::translation_of(e.pose.mean);
  Eigen::Quaterniond q = opf::orientation_of(e.pose.mean);
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  p.quaternion = q.coeffs();  // Eigen stores x, y, z, w
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) p.covariance(i, j) = e.pose.cov(i, j);
  p.trace = e.observation_trace;
  p.mode = opf::mode_column(e.mode, e.recovery);
  p.hypothesis = e.hypothesis;
  p.probability = e.probability;
  p.alert = e.alert;
  p.model = e.motion_model;
  return p;
}

// Settings from None (the defaults), a path to a settings file, or a dict in the file's shape
// (converted to YAML text and read by the same reader, so the same checks and messages apply).
opf::EstimatorSettings settings_from(const py::object& config) {
  if (config.is_none()) return {};
  if (py::isinstance<py::dict>(config)) {
    const py::object json = py::module_::import("json");
    // JSON is YAML: the reader sees the dict exactly as a settings file with the same keys.
    const std::string text = py::cast<std::string>(json.attr("dumps")(config));
    return opf::parse_estimator_settings(text, "<config dict>");
  }
  const py::object fspath = py::module_::import("os").attr("fspath");
  return opf::load_estimator_settings(py::cast<std::string>(fspath(config)));
}

opf::EstimatorSettings configured(const py::object& config, std::optional<std::size_t> particles) {
  opf::EstimatorSettings settings = settings_from(config);
  if (particles) {
    if (*particles == 0) throw std::invalid_argument("particles must be at least 1");
    settings.pf.translation_particles = settings.pf.rotation_particles = *particles;
  }
  return settings;
}

class PyTracker {
 public:
  PyTracker(const std::string& estimator, std::uint64_t seed, std::optional<std::size_t> particles,
            const py::object& config)
      : tracker_(opf::make_estimator_factory(estimator, configured(config, particles)), seed) {}

  std::map<std::string, PyEstimate> step(
      double t, const std::map<std::string, std::optional<Pose7>>& detections) {
    opf::Frame frame;
    frame.t = t;
    for (const auto& [object, pose] : detections) {
      if (!pose) continue;  // None: unobserved in this frame
      const Pose7& p = *pose;
      const Eigen::Quaterniond q(p[6], p[3], p[4], p[5]);
      if (std::abs(q.norm() - 1.0) > 0.01)
        throw std::invalid_argument("object '" + object + "': the quaternion (qx, qy, qz, qw) " +
                                    "must have unit norm");
      frame.detections.push_back(
          {object, opf::make_pose(Eigen::Vector3d(p[0], p[1], p[2]), q.normalized())});
    }
    std::map<std::string, PyEstimate> out;
    {
      py::gil_scoped_release release;
      tracker_.step(frame);
    }
    for (const opf::Estimate& e : tracker_.estimates()) out.emplace(e.object, to_python(e));
    return out;
  }

  std::vector<PyEstimate> hypotheses() const {
    std::vector<PyEstimate> out;
    for (const opf::Estimate& e : tracker_.hypotheses()) out.push_back(to_python(e));
    return out;
  }

 private:
  opf::Tracker tracker_;
};

// The columns of an estimate file, as numpy arrays (objects and modes as lists of str).
py::dict track_log(const std::string& path, const std::string& estimator, std::uint64_t seed,
                   std::optional<std::size_t> particles, const py::object& config) {
  const opf::EstimatorSettings settings = configured(config, particles);
  std::vector<double> t, x, y, z, qx, qy, qz, qw, trace, probability;
  std::vector<std::string> object, mode, model;
  std::vector<int> hypothesis;
  std::vector<bool> alert;
  {
    py::gil_scoped_release release;
    const opf::MeasurementLog log = opf::read_measurement_log(path);
    opf::Tracker tracker(opf::make_estimator_factory(estimator, settings), seed);
    const auto record = [&](opf::Estimate e, bool filled) {
      e.recovery.frame_filled = filled;
      const PyEstimate p = to_python(e);
      t.push_back(p.t);
      object.push_back(p.object);
      x.push_back(p.position.x());
      y.push_back(p.position.y());
      z.push_back(p.position.z());
      qx.push_back(p.quaternion(0));
      qy.push_back(p.quaternion(1));
      qz.push_back(p.quaternion(2));
      qw.push_back(p.quaternion(3));
      trace.push_back(p.trace);
      mode.push_back(p.mode);
      hypothesis.push_back(p.hypothesis);
      probability.push_back(p.probability);
      alert.push_back(p.alert);
      model.push_back(p.model);
    };
    for (const opf::Frame& frame : log.frames) {
      for (const opf::Estimate& e : tracker.step(frame)) record(e, frame.filled);
      for (const opf::Estimate& e : tracker.hypotheses()) record(e, frame.filled);
    }
  }
  py::dict columns;
  columns["t"] = py::array(py::cast(t));
  columns["object"] = py::cast(object);
  columns["x"] = py::array(py::cast(x));
  columns["y"] = py::array(py::cast(y));
  columns["z"] = py::array(py::cast(z));
  columns["qx"] = py::array(py::cast(qx));
  columns["qy"] = py::array(py::cast(qy));
  columns["qz"] = py::array(py::cast(qz));
  columns["qw"] = py::array(py::cast(qw));
  columns["trace"] = py::array(py::cast(trace));
  columns["mode"] = py::cast(mode);
  columns["hypothesis"] = py::array(py::cast(hypothesis));
  columns["probability"] = py::array(py::cast(probability));
  columns["alert"] = py::array(py::cast(alert));
  columns["model"] = py::cast(model);
  return columns;
}

}  // namespace

PYBIND11_MODULE(_opf, m) {
  m.doc() = "Object Permanence Filter toolkit: trackers and log replay (compiled part of `opf`)";
  py::register_exception<opf::InputError>(m, "InputError", PyExc_ValueError);

  py::class_<PyEstimate>(m, "Estimate", "One object's estimate at one frame.")
      .def_readonly("object", &PyEstimate::object)
      .def_readonly("t", &PyEstimate::t)
      .def_readonly("position", &PyEstimate::position, "x, y, z (m)")
      .def_readonly("quaternion", &PyEstimate::quaternion, "qx, qy, qz, qw (qw >= 0)")
      .def_readonly("covariance", &PyEstimate::covariance,
                    "6x6 over (x, y, z, yaw, pitch, roll), MRPT's convention")
      .def_readonly("trace", &PyEstimate::trace,
                    "trace of the observation covariance used at the step (trace(Q~))")
      .def_readonly("mode", &PyEstimate::mode,
                    "what produced it: measured, predicted, dynamics, carried, left, random_walk "
                    "(+ recovery events), as in estimate files")
      .def_readonly("hypothesis", &PyEstimate::hypothesis, "0: main; 1, 2, ...: further")
      .def_readonly("probability", &PyEstimate::probability,
                    "the hypothesis's probability among the object's (1 when it is the only one)")
      .def_readonly("alert", &PyEstimate::alert, "the safety alert: trace >= epsilon_safe")
      .def_readonly("model", &PyEstimate::model, "the dynamics module's motion models, if any")
      .def("__repr__", [](const PyEstimate& e) {
        return "<opf.Estimate " + e.object + " t=" + std::to_string(e.t) + " mode=" + e.mode + ">";
      });

  py::class_<PyTracker>(m, "Tracker",
                        "One estimator per object, stepped frame by frame (opf::Tracker).")
      .def(py::init<const std::string&, std::uint64_t, std::optional<std::size_t>,
                    const py::object&>(),
           py::arg("estimator") = "opf", py::arg("seed") = 1, py::arg("particles") = 5000,
           py::arg("config") = py::none(),
           "estimator: opf, pf, cvkf, imm or oapf; particles: per portion (None: the config's); "
           "config: None (the defaults), a settings file's path, or a dict in its shape")
      .def("step", &PyTracker::step, py::arg("t"), py::arg("detections"),
           "t in seconds (increasing); detections: {object: [x, y, z, qx, qy, qz, qw] or None}. "
           "Returns {object: Estimate} for every object seen so far.")
      .def_property_readonly("hypotheses", &PyTracker::hypotheses,
                             "further hypotheses (hypothesis >= 1) after the last step");

  m.def("_track_log", &track_log, py::arg("path"), py::arg("estimator") = "opf",
        py::arg("seed") = 1, py::arg("particles") = 5000, py::arg("config") = py::none());
  m.def(
      "estimators", [] { return opf::estimator_names(); }, "The estimator names Tracker accepts.");
}
