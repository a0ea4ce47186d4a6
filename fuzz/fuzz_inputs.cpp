#include "fuzz_inputs.h"

#include "estimators/estimator_settings_yaml.h"
#include "io/input_error.h"
#include "io/measurement_log.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace opf::fuzz {
namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::logic_error("fuzz: " + what);
}

}  // namespace

void measurement_log(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const MeasurementLog log = parse_measurement_log(in, "fuzz.csv");
    // What the reader accepts keeps its promises: frames in increasing time, finite poses.
    for (std::size_t k = 1; k < log.frames.size(); ++k)
      if (!(log.frames[k - 1].t < log.frames[k].t)) fail("frames out of order");
    for (const Frame& frame : log.frames)
      for (const Detection& d : frame.detections)
        for (const double v : d.pose.asVectorVal())
          if (!std::isfinite(v)) fail("a non-finite pose was accepted");
  } catch (const InputError&) {
  }
}

void estimator_settings(const std::uint8_t* data, std::size_t size) {
  try {
    parse_estimator_settings(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  } catch (const InputError&) {
  }
}

}  // namespace opf::fuzz
