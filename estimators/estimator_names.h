#pragma once
// The names the registry builds estimators by (registry.h), and the message for any other name.

#include <string>
#include <vector>

namespace opf {

/// The names `make_estimator_factory` accepts, in the order tables list them.
std::vector<std::string> estimator_names();

/// "unknown estimator 'NAME' (known: ...)", with "; did you mean 'M'?" for a near miss.
std::string unknown_estimator_message(const std::string& name);

}  // namespace opf
