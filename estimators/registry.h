#pragma once
// Builds any estimator by its registry name ("pf", "cvkf", ...) with its options.

#include "opf/core/tracker.h"
#include "opf/estimators/estimator_names.h"
#include "opf/estimators/estimator_settings.h"

#include <string>

namespace opf {

/// A factory for the Tracker. Throws std::invalid_argument naming the known estimators when
/// `name` is unknown.
EstimatorFactory make_estimator_factory(const std::string& name, const EstimatorSettings& settings);

}  // namespace opf
