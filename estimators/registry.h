#pragma once
// Builds any estimator by its registry name ("pf", "cvkf", ...) with its options.

#include "opf/core/tracker.h"
#include "opf/estimators/estimator_settings.h"

#include <string>
#include <vector>

namespace opf {

/// The names `make_estimator_factory` accepts, in the order tables list them.
std::vector<std::string> estimator_names();

/// "unknown estimator 'NAME' (known: ...)", with "; did you mean 'M'?" for a near miss.
std::string unknown_estimator_message(const std::string& name);

/// A factory for the Tracker. Throws std::invalid_argument naming the known estimators when
/// `name` is unknown.
EstimatorFactory make_estimator_factory(const std::string& name, const EstimatorSettings& settings);

}  // namespace opf
