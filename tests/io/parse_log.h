#pragma once
// Reading a log from text in the io tests: the log, or the InputError it is refused with.

#include "opf/io/input_error.h"
#include "opf/io/measurement_log.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace opf {

inline MeasurementLog parse(const std::string& text, const LogReadOptions& options = {}) {
  std::istringstream in(text);
  return parse_measurement_log(in, "log.csv", options);
}

inline InputError parse_error(const std::string& text, const LogReadOptions& options = {}) {
  try {
    parse(text, options);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", 0, "", "");
}

}  // namespace opf
