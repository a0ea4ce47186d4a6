#include "opf/estimators/estimator_names.h"

#include "opf/core/closest_name.h"

namespace opf {

std::vector<std::string> estimator_names() {
  return {"opf", "pf", "cvkf", "imm", "oapf"};
}

std::string unknown_estimator_message(const std::string& name) {
  std::string known;
  for (const auto& n : estimator_names()) known += (known.empty() ? "" : ", ") + n;
  std::string message = "unknown estimator '" + name + "' (known: " + known + ")";
  if (const auto closest = closest_name(name, estimator_names()))
    message += "; did you mean '" + *closest + "'?";
  return message;
}

}  // namespace opf
