// The Python module `opf` (its compiled part, opf._opf): the Tracker stepped from Python, and a
// whole measurement log replayed in C++ into column arrays. Errors keep their C++ messages
// (InputError and std::invalid_argument as ValueError, other failures as RuntimeError); the GIL
// is released while the estimators run. The parts: py_tracker (Tracker), track_log and its
// options, settings_arguments (preset, config, camera, particles), py_estimate (Estimate).
#include "py_estimate.h"
#include "py_tracker.h"
#include "settings_arguments.h"
#include "track_log.h"

#include "opf/estimators/registry.h"
#include "opf/io/input_error.h"

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <string>

#ifndef OPF_PYTHON_VERSION
#error "OPF_PYTHON_VERSION (the project's version) is set by python/CMakeLists.txt"
#endif

namespace py = pybind11;
using opf::python::PyEstimate;
using opf::python::PyTracker;

namespace {

// A message as Python text: the header of a binary file, quoted in a message, is not UTF-8 and
// would leave the message empty. Control characters and bytes that are not UTF-8 become \xNN
// escapes; the text is what() and so, as opf track's, ends at a NUL byte.
py::str readable(const std::string& message) {
  std::string text;
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte < 0x20 && c != '\t') || byte == 0x7f) {
      char escape[5];
      std::snprintf(escape, sizeof escape, "\\x%02x", byte);
      text += escape;
    } else {
      text += c;
    }
  }
  PyObject* decoded =
      PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "backslashreplace");
  if (decoded == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(decoded);
}

void translate_input_error(std::exception_ptr error) {
  try {
    if (error) std::rethrow_exception(error);
  } catch (const opf::InputError& e) {
    // The message, and where it points as attributes: file, line (0: none), field ("" : none).
    const py::object type = py::module_::import("opf._opf").attr("InputError");
    const py::object instance = type(readable(e.what()));
    instance.attr("file") = readable(e.file());
    instance.attr("line") = e.line();
    instance.attr("field") = readable(e.field());
    instance.attr("reason") = readable(e.message());
    PyErr_SetObject(type.ptr(), instance.ptr());
  }
}

void bind_estimate(py::module_& m) {
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
}

void bind_tracker(py::module_& m) {
  const auto make = [](const std::string& estimator, std::uint64_t seed,
                       std::optional<std::size_t> particles, const py::object& config,
                       const std::string& preset, const py::object& camera) {
    return std::make_unique<PyTracker>(
        estimator, seed,
        opf::python::SettingsArguments{
            .preset = preset, .config = config, .camera = camera, .particles = particles});
  };
  py::class_<PyTracker>(m, "Tracker",
                        "One estimator per object, stepped frame by frame (opf::Tracker). One "
                        "step at a time: calls from several threads take turns.")
      .def(py::init(make), py::arg("estimator") = "opf", py::arg("seed") = 1,
           py::arg("particles") = py::none(), py::arg("config") = py::none(),
           py::arg("preset") = "default", py::arg("camera") = py::none(),
           "estimator: opf, pf, cvkf, imm or oapf; particles: per portion (None: the config's, "
           "else 5000; a config setting another count is refused); config: None (the "
           "defaults), a settings file's path, or a dict in its shape; preset: default or "
           "paper (the config applies on top); camera: [X, Y, Z] or \"X,Y,Z\" (m), where the "
           "occluder module's line of sight starts, or [X, Y, Z, 0] for a camera infinitely far "
           "in that direction, as opf track --camera")
      .def("step", &PyTracker::step, py::arg("t"), py::arg("detections"),
           "t in seconds (increasing); detections: {object: [x, y, z, qx, qy, qz, qw] or None}, "
           "or [x, y, z] for a position alone (at the identity orientation); an eighth number the "
           "detection's stated extra noise (m), a ninth the object's stated "
           "radius (m), a tenth to twelfth its box's full extents box_x, box_y, box_z (m, each "
           "> 0, all three or none). Returns {object: Estimate} "
           "for every object seen so far. A non-finite or malformed "
           "input raises ValueError naming the object and the field, and leaves the tracker as "
           "it was.")
      .def_property_readonly("hypotheses", &PyTracker::hypotheses,
                             "further hypotheses (hypothesis >= 1) after the last step");
}

void bind_track_log(py::module_& m) {
  m.def(
      "_track_log",
      [](const std::string& path, const std::string& estimator, std::uint64_t seed,
         std::optional<std::size_t> particles, const py::object& config, const std::string& preset,
         const py::object& camera, std::optional<std::string> format,
         std::optional<std::string> object, std::optional<std::string> time_unit,
         std::optional<std::string> length_unit, const py::object& columns,
         std::optional<double> frame_tolerance, std::optional<double> rate, bool fill,
         bool covariance) {
        return opf::python::track_log(
            {.path = path,
             .estimator = estimator,
             .seed = seed,
             .settings = {preset, config, camera, particles},
             .log = {format, object, time_unit, length_unit, columns, frame_tolerance, rate, fill},
             .covariance = covariance});
      },
      py::arg("path"), py::arg("estimator") = "opf", py::arg("seed") = 1,
      py::arg("particles") = py::none(), py::arg("config") = py::none(),
      py::arg("preset") = "default", py::arg("camera") = py::none(), py::arg("format") = py::none(),
      py::arg("object") = py::none(), py::arg("time_unit") = py::none(),
      py::arg("length_unit") = py::none(), py::arg("columns") = py::none(),
      py::arg("frame_tolerance") = py::none(), py::arg("rate") = py::none(), py::arg("fill") = true,
      py::arg("covariance") = false);
}

}  // namespace

PYBIND11_MODULE(_opf, m) {
  m.doc() = "Object Permanence Filter toolkit: trackers and log replay (compiled part of `opf`)";
  m.attr("__version__") = OPF_PYTHON_VERSION;
  // The type only: translate_input_error raises it with the whole message.
  py::exception<opf::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception_translator(&translate_input_error);
  bind_estimate(m);
  bind_tracker(m);
  bind_track_log(m);
  m.def(
      "estimators", [] { return opf::estimator_names(); }, "The estimator names Tracker accepts.");
}
